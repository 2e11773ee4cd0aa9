#include <gtest/gtest.h>

#include <set>

#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "io/imageIO.h"
#include "particleSolid/makeParticleSolid.h"
#include "particleSolid/particleSolidReport.h"

namespace solidtex {
namespace {

// A photo that exists only in memory: 40 dark discs of radius 5 to 8 on a light ground, apart.
cv::Mat discsPhoto() {
  cv::Mat photo(160, 160, CV_32FC3, cv::Scalar(0.85, 0.82, 0.78));
  cv::RNG rng(7);
  for (int row = 0; row < 8; ++row)
    for (int col = 0; col < 5; ++col) {
      const cv::Point centre(12 + col * 32 + rng.uniform(-3, 4), 10 + row * 20 + rng.uniform(-1, 2));
      cv::circle(photo, centre, rng.uniform(5, 9) - (row % 2), cv::Scalar(0.25, 0.2, 0.15), cv::FILLED,
                 cv::LINE_8);
    }
  return photo;
}

ParticleSolidOptions smallSolid(int size) {
  ParticleSolidOptions options;
  options.dims = {size, size, size};
  options.seed = 3;
  return options;
}

// The fits and the matrix synthesis set aside, for tests of what does not depend on them.
ParticleSolidOptions quickSolid(int size) {
  ParticleSolidOptions options = smallSolid(size);
  options.smoothing = 0.2;
  options.matrix = Texture::Projected;
  return options;
}

TEST(MakeParticleSolid, AnInMemoryPhotoGivesASolidWithItsAreaFraction) {
  std::set<std::string> steps;
  const ParticleSolid solid = makeParticleSolid(
      discsPhoto(), "discs", smallSolid(48),
      [&](const std::string& step, double) { steps.insert(step.substr(0, step.find(':'))); });
  EXPECT_EQ(solid.stats.particles.size(), 40u);
  ASSERT_EQ(solid.volume.particleId.size(), solid.volume.dims.count());
  ASSERT_TRUE(solid.volume.hasColor());
  std::size_t inside = 0;
  std::set<std::int32_t> ids;
  for (const std::int32_t id : solid.volume.particleId)
    if (id > 0) ++inside, ids.insert(id);
  const double fraction = double(inside) / double(solid.volume.dims.count());
  // Placement stops within one particle of the photo's fraction; the open boundary's crop moves it
  // by the particles cut at the faces.
  EXPECT_NEAR(fraction, solid.stats.areaFraction, 0.03);
  EXPECT_DOUBLE_EQ(fraction, solid.placement.volumeFraction);
  EXPECT_EQ(ids.size(), solid.placement.particles.size());
  for (const char* step :
       {"segmenting the photo", "building particle shapes", "sizing particles from their sections",
        "placing particles", "synthesizing the matrix", "painting the particles"})
    EXPECT_TRUE(steps.count(step)) << step;
  const nlohmann::json form = particleSolidReport(solid, smallSolid(48))["body_form"];
  EXPECT_EQ(form["form"], 0);  // the paper's boxes unless asked
  EXPECT_FALSE(form["fitted"]);
}

TEST(MakeParticleSolid, TheStagesGiveTheOneOffFormsVolume) {
  const cv::Mat photo = discsPhoto();
  const ParticleSolid once = makeParticleSolid(photo, "discs", quickSolid(32));
  ParticleSolidBuilder builder(quickSolid(32));
  EXPECT_EQ(builder.analyze(photo, "discs").particles.size(), once.stats.particles.size());
  builder.makeParticles();
  EXPECT_EQ(builder.place().particles.size(), once.placement.particles.size());
  ParticleSolid staged = builder.finish();
  EXPECT_EQ(staged.volume.particleId, once.volume.particleId);
  SolidVolume painted = once.volume;
  paintColor(painted);
  paintColor(staged.volume);
  EXPECT_EQ(staged.volume.color, painted.color);
  EXPECT_EQ(particleSolidReport(staged, quickSolid(32)), particleSolidReport(once, quickSolid(32)));
}

TEST(MakeParticleSolid, OptionsOutOfRangeAreRefusedBeforeAnyWork) {
  ParticleSolidOptions options = smallSolid(4);
  EXPECT_THROW(ParticleSolidBuilder{options}, OptionError);
  options = smallSolid(32);
  options.particles.views = 7;
  EXPECT_THROW(ParticleSolidBuilder{options}, OptionError);
}

TEST(MakeParticleSolid, ABodyFormIsRefusedForThreePhotosWhoseParticlesKeepTheirAxes) {
  ParticleSolidOptions options = quickSolid(32);
  options.bodyForm = 0.5;
  ParticleSolidBuilder builder(options);
  const cv::Mat photo = discsPhoto();
  builder.analyze(photo, "discs");
  cv::Mat other;
  cv::flip(photo, other, 0);
  EXPECT_THROW(builder.analyzePlanes(other, "xz", other, "yz"), OptionError);
  options.bodyForm = std::nullopt;  // auto: the aligned boxes are kept, not refused
  ParticleSolidBuilder fitted(options);
  fitted.analyze(photo, "discs");
  EXPECT_NO_THROW(fitted.analyzePlanes(other, "xz", other, "yz"));
}

}  // namespace
}  // namespace solidtex
