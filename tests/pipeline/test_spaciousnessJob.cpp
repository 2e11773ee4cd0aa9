#include <gtest/gtest.h>

#include <cmath>

#include "pipeline/spaciousnessJob.h"

namespace solidtex {
namespace {

// The four fields on one scene of coins.png against the exact distances: what each kind promises.
TEST(SpaciousnessJob, EachFieldKeepsItsPromiseOnAPhotosScene) {
  SpaciousnessJob job;
  job.photo = std::string(SOLIDTEX_DATA_DIR) + "/particles/coins.png";
  job.size = 40;
  job.particles = 25;
  job.progress = false;
  const nlohmann::json r = runSpaciousness(job);
  EXPECT_EQ(r["particles"].get<int>(), 25);
  const auto& fields = r["fields"];
  for (const char* exact : {"edt", "brute"})
    EXPECT_EQ(fields[exact]["all_voxels"]["max_abs_error"].get<double>(), 0) << exact;
  // Delaunay's at() is a bound from a sample of the surface: never above, at most a voxel (and the jitter)
  // below.
  EXPECT_LE(fields["delaunay"]["all_voxels"]["max_error"].get<double>(), 1e-4);
  EXPECT_LE(fields["delaunay"]["all_voxels"]["max_abs_error"].get<double>(), 1.02);
  // Discrete underestimates, by at most the share 1 - 1/sqrt(3) of the value.
  const double largest = r["largest_exact_empty_ball"].get<double>();
  EXPECT_LE(fields["discrete"]["all_voxels"]["mean_error"].get<double>(), 0);
  EXPECT_LE(fields["discrete"]["all_voxels"]["max_abs_error"].get<double>(),
            largest * (1 - 1 / std::sqrt(3.0)) + 1e-4);
  // Circumsphere candidates exceed the exact value by at most the slack (one voxel), and the largest is
  // the largest empty ball within a voxel.
  EXPECT_LE(fields["delaunay"]["circumcentres"]["max_error"].get<double>(), 1 + 1e-4);
  const double candidate = r["largest_circumsphere_candidate"].get<double>();
  EXPECT_LE(candidate, largest + 1 + 1e-4);
  EXPECT_GE(candidate, largest - 1);
  for (const char* exact : {"edt", "brute"})
    for (const auto& fit : fields[exact]["best_fit"]) EXPECT_TRUE(fit["agrees"].get<bool>()) << exact;
}

}  // namespace
}  // namespace solidtex
