#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>
#include <vector>

#include "pipeline/compareJob.h"
#include "pipeline/particleSolidJob.h"
#include "pipeline/synthesizeJob.h"
#include "tests/scratchPath.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) { return test::scratchPath("report_test", name); }

// Every key of every object, at any depth, that is not snake_case.
void collectOtherKeys(const nlohmann::json& json, std::vector<std::string>& out) {
  static const std::regex snake("[a-z0-9]+(_[a-z0-9]+)*");
  if (json.is_object()) {
    for (const auto& [key, value] : json.items()) {
      if (!std::regex_match(key, snake)) out.push_back(key);
      collectOtherKeys(value, out);
    }
  } else if (json.is_array()) {
    for (const auto& value : json) collectOtherKeys(value, out);
  }
}

std::vector<std::string> otherKeys(const nlohmann::json& json) {
  std::vector<std::string> out;
  collectOtherKeys(json, out);
  return out;
}

TEST(Reports, SynthesizeReportIsSnakeCaseWithLevelsAndMemory) {
  SynthesizeJob job;
  job.exemplar = std::string(SOLIDTEX_DATA_DIR) + "/continuous/walnut.png";
  job.output = scratch("synthesized.vdb").string();
  job.synthesis.size = 16;
  job.synthesis.levels = 2;
  job.synthesis.neighborhoods = {4};
  job.synthesis.iterations = 1;
  job.progress = false;
  const nlohmann::json report = runSynthesize(job);
  EXPECT_EQ(otherKeys(report), std::vector<std::string>{});
  ASSERT_EQ(report["level_reports"].size(), 2u);
  EXPECT_EQ(report["level_reports"][1]["volume_size"], 16);
  EXPECT_GT(report["peak_memory_mib"].get<double>(), 0.0);
  EXPECT_TRUE(report["quality"]["axis"].contains("completeness"));
  // Auto mode reads the particle ids first; a continuous solid has none and is read whole.
  CompareJob compare;
  compare.photo = job.exemplar;
  compare.volume = job.output;
  const nlohmann::json compared = runCompare(compare);
  EXPECT_EQ(compared["mode"], "continuous");
  EXPECT_EQ(otherKeys(compared), std::vector<std::string>{});
  fs::remove(job.output);
}

TEST(Reports, PlaneExemplarsRateEachPlaneAndCompareRatesOnePlane) {
  const std::string planes = std::string(SOLIDTEX_DATA_DIR) + "/continuous/planes/";
  SynthesizeJob job;
  job.exemplar = planes + "wood_xy.png";
  job.photoXz = planes + "wood_xz.png";
  job.photoYz = planes + "wood_yz.png";
  job.output = scratch("planes.vdb").string();
  job.synthesis.size = 16;
  job.synthesis.levels = 2;
  job.synthesis.neighborhoods = {4};
  job.synthesis.iterations = 1;
  job.progress = false;
  job.quality.patches = 1024;
  const nlohmann::json report = runSynthesize(job);
  EXPECT_EQ(otherKeys(report), std::vector<std::string>{});
  EXPECT_FALSE(report.contains("quality"));  // one exemplar does not speak for every axis
  for (const char* plane : {"yz", "xz", "xy"})
    EXPECT_EQ(report["planes"][plane]["exemplar"], std::string("wood_") + plane + ".png");
  CompareJob compare;
  compare.photo = *job.photoXz;
  compare.volume = job.output;
  compare.sections.planeAxis = 1;
  compare.quality = job.quality;
  const nlohmann::json compared = runCompare(compare);
  EXPECT_EQ(compared["mode"], "continuous");
  EXPECT_EQ(compared["plane"], "xz");
  EXPECT_NEAR(compared["quality"]["axis"]["completeness"].get<double>(),
              report["planes"]["xz"]["quality"]["axis"]["completeness"].get<double>(), 1e-9);
  fs::remove(job.output);
}

TEST(Reports, ParticlesAndCompareReportsAreSnakeCase) {
  ParticleSolidJob job;
  job.photo = std::string(SOLIDTEX_DATA_DIR) + "/particles/smarties.png";
  job.output = scratch("particles.vdb").string();
  job.dims = {40, 40, 40};
  job.progress = false;
  EXPECT_EQ(otherKeys(runParticleSolid(job)), std::vector<std::string>{});
  CompareJob compare;
  compare.photo = job.photo;
  compare.volume = job.output;
  EXPECT_EQ(otherKeys(runCompare(compare)), std::vector<std::string>{});
  fs::remove(job.output);
}

}  // namespace
}  // namespace solidtex
