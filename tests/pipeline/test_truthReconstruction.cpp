#include <gtest/gtest.h>

#include <filesystem>
#include <map>

#include "common/Error.h"
#include "pipeline/compareJob.h"
#include "pipeline/particleSolidJob.h"
#include "pipeline/truthJob.h"

namespace solidtex {
namespace {

namespace fs = std::filesystem;

struct TruthCase {
  const char* name;
  double volumeFraction;
  std::uint64_t seed;
};

class ReconstructionOfATruth : public testing::TestWithParam<TruthCase> {};

// A photo cut from a known 3D truth, rebuilt at 128^3 with both sizings: section sizing must match the
// photo's section areas and the truth's particle volumes, and beat the paper's box sizing on both.
TEST_P(ReconstructionOfATruth, SectionSizingMatchesThePhotoAndTheTruth) {
  const fs::path dir = fs::temp_directory_path() / "solidtex_truth_test" / GetParam().name;
  fs::remove_all(dir);
  TruthJob truth;
  truth.folder = dir.string();
  truth.truth.volumeFraction = GetParam().volumeFraction;
  truth.truth.seed = GetParam().seed;
  runTruth(truth);

  std::map<Sizing, nlohmann::json> comparison;
  for (const Sizing sizing : {Sizing::Bbox, Sizing::Sections}) {
    ParticleSolidJob job;
    job.photo = (dir / "photo.png").string();
    job.output = (dir / (std::string(sizingName(sizing)) + ".vdb")).string();
    job.sizing = sizing;
    job.progress = false;
    runParticleSolid(job);
    CompareJob compare;
    compare.photo = job.photo;
    compare.volume = job.output;
    compare.truth = (dir / "truth.vdb").string();
    comparison[sizing] = runCompare(compare);
  }
  const nlohmann::json& sections = comparison[Sizing::Sections];
  const nlohmann::json& bbox = comparison[Sizing::Bbox];
  EXPECT_NEAR(sections["volume_fraction"].get<double>(), sections["area_fraction"].get<double>(), 0.02);
  EXPECT_LE(sections["ks"].get<double>(), 0.12);
  EXPECT_LE(sections["truth"]["volume_wasserstein1_over_mean"].get<double>(), 0.3);
  EXPECT_LT(sections["ks"].get<double>(), bbox["ks"].get<double>());
  EXPECT_LT(sections["truth"]["volume_wasserstein1_over_mean"].get<double>(),
            bbox["truth"]["volume_wasserstein1_over_mean"].get<double>());
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Ellipsoids, ReconstructionOfATruth,
                         testing::Values(TruthCase{"sparse", 0.2, 1}, TruthCase{"crowded", 0.3, 1}),
                         [](const testing::TestParamInfo<TruthCase>& info) { return std::string(info.param.name); });

TEST(TruthJob, RefusesAFolderItCannotCreate) {
  TruthJob job;
  job.truth.dims = {64, 64, 64};
  job.folder = "/proc/solidtex-truth";
  EXPECT_THROW(runTruth(job), InputError);
}

} // namespace
} // namespace solidtex
