#include <cmath>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/runSolidtex.h"

namespace solidtex::testing {
namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool kSanitized = true;  // shadow memory multiplies what the process holds
#else
constexpr bool kSanitized = false;
#endif

// The memory check's estimate, which it also reports, is within a quarter of the peak the run then
// reaches, at two sizes (the open boundary's block 1.9 and 1.7 times the volume).
TEST(MemoryEstimate, IsWithinAQuarterOfThePeakAtTwoSizes) {
  if (kSanitized) GTEST_SKIP() << "a sanitized build holds several times the memory";
  for (const int size : {96, 160}) {
    const fs::path dir = scratch("memoryEstimate" + std::to_string(size));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const Outcome outcome =
        runSolidtex("particles " + shellWord(std::string(SOLIDTEX_DATA_DIR) + "/particles/gravel.png") +
                    " -o " + shellWord(dir / "g.vdb") + " --size " + std::to_string(size) +
                    " --threads 2 --quiet --report " + shellWord(dir / "r.json"));
    ASSERT_EQ(outcome.exitCode, 0) << size;
    const auto report = nlohmann::json::parse(readFile(dir / "r.json"));
    const double peak = report["peak_memory_mib"].get<double>();
    const double estimate = report["memory_estimate_mib"].get<double>();
    EXPECT_LT(std::abs(estimate - peak), 0.25 * peak)
        << size << "^3: estimate " << estimate << " MiB, peak " << peak;
    fs::remove_all(dir);
  }
}

}  // namespace
}  // namespace solidtex::testing
