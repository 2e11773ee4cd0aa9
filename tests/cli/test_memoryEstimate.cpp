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

// Runs `solidtex COMMAND -o OUT.vdb --threads 2 --quiet --report R.json` in a scratch folder and
// expects the report's memory estimate within a quarter of its peak.
void expectEstimateWithinAQuarterOfThePeak(const std::string& name, const std::string& command) {
  const fs::path dir = scratch(name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  const Outcome outcome = runSolidtex(command + " -o " + shellWord(dir / "out.vdb") +
                                      " --threads 2 --quiet --report " + shellWord(dir / "r.json"));
  ASSERT_EQ(outcome.exitCode, 0) << command;
  const auto report = nlohmann::json::parse(readFile(dir / "r.json"));
  const double peak = report["peak_memory_mib"].get<double>();
  const double estimate = report["memory_estimate_mib"].get<double>();
  EXPECT_LT(std::abs(estimate - peak), 0.25 * peak)
      << command << ": estimate " << estimate << " MiB, peak " << peak;
  fs::remove_all(dir);
}

// The memory check's estimate, which it also reports, is within a quarter of the peak the run then
// reaches, at two sizes (the open boundary's block 1.9 and 1.7 times the volume).
TEST(MemoryEstimate, IsWithinAQuarterOfThePeakAtTwoSizes) {
  if (kSanitized) GTEST_SKIP() << "a sanitized build holds several times the memory";
  const std::string gravel = shellWord(std::string(SOLIDTEX_DATA_DIR) + "/particles/gravel.png");
  for (const int size : {96, 160})
    expectEstimateWithinAQuarterOfThePeak("memoryEstimate" + std::to_string(size),
                                          "particles " + gravel + " --size " + std::to_string(size));
}

// The same for a grown photo solid, whole and in bricks (the larger seeds, whose analysis makes the
// peak, take minutes: docs/performance.md).
TEST(MemoryEstimate, OfAGrownSolidIsWithinAQuarterOfThePeak) {
  if (kSanitized) GTEST_SKIP() << "a sanitized build holds several times the memory";
  const std::string photo = shellWord(std::string(SOLIDTEX_DATA_DIR) + "/continuous/pink_marble.png");
  expectEstimateWithinAQuarterOfThePeak("memoryEstimateGrown40",
                                        "synthesize " + photo + " --dims 64 64 64 --grow-from 40");
  expectEstimateWithinAQuarterOfThePeak(
      "memoryEstimateGrown48", "synthesize " + photo + " --dims 128 64 48 --bricks 48 --grow-from 48");
}

}  // namespace
}  // namespace solidtex::testing
