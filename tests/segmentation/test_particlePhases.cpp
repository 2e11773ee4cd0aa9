#include <gtest/gtest.h>

#include <array>
#include <map>
#include <set>

#include "common/Error.h"
#include "segmentation/analyzeExemplar.h"
#include "segmentation/particlePhases.h"
#include "validation/particleTruth.h"

namespace solidtex {
namespace {

// A truth's middle section: small orange and large blue particles, or with a third class, green.
ExemplarStats truthPhoto(bool threeClasses, std::uint64_t seed) {
  ParticleTruthOptions options;
  options.dims = {320, 320, 48};
  options.classes[0].meanRadius = 5;
  options.classes[1].meanRadius = 10;
  if (threeClasses) {
    options.classes[0].share = 0.45;
    options.classes.insert(options.classes.begin() + 1, ParticleClass{7.5, 0.2, 0.3, {0.35f, 0.75f, 0.30f}});
  }
  options.seed = seed;
  return analyzeExemplar(makeParticleTruth(options).photo, "truth", {});
}

// b* > 0 orange, a* < -20 green, else blue: the truth's colours apart.
int truthClassOf(const cv::Mat& centres, int row) {
  if (centres.at<float>(row, 1) < -20) return 2;
  return centres.at<float>(row, 2) > 0 ? 0 : 1;
}

// The count the BIC chooses is the truth's, on two seeds each: the colours shading and noise spread
// each class's over stay one phase, and every class is one.
TEST(ParticlePhases, TheColoursBicFindsTheTruthsClasses) {
  for (const bool three : {false, true})
    for (const std::uint64_t seed : {1, 2}) {
      const ExemplarStats stats = truthPhoto(three, seed);
      const ParticlePhases phases = classifyParticles(stats, kAutoPhases, 1);
      ASSERT_EQ(phases.centres.rows, three ? 3 : 2) << "seed " << seed;
      ASSERT_EQ(phases.bic.size(), 8u);
      std::set<int> classes;
      for (int r = 0; r < phases.centres.rows; ++r) classes.insert(truthClassOf(phases.centres, r));
      EXPECT_EQ(int(classes.size()), phases.centres.rows);
      // Darkest first.
      for (int r = 1; r < phases.centres.rows; ++r)
        EXPECT_LE(phases.centres.at<float>(r - 1, 0), phases.centres.at<float>(r, 0));
    }
}

// Each phase's particles, and only they, have its colour; its share of the area adds up to the
// photo's particle fraction; the phase's own statistics hold its particles alone.
TEST(ParticlePhases, PhasesSplitTheParticlesAndTheirArea) {
  ExemplarStats stats = truthPhoto(false, 3);
  assignPhases(stats, classifyParticles(stats, 2, 7));
  const std::vector<double> fractions = phaseAreaFractions(stats);
  ASSERT_EQ(fractions.size(), 2u);
  EXPECT_NEAR(fractions[0] + fractions[1], stats.areaFraction, 1e-9);
  std::size_t total = 0;
  for (int k = 0; k < 2; ++k) {
    const ExemplarStats phase = phaseStats(stats, k);
    total += phase.particles.size();
    EXPECT_NEAR(phase.areaFraction, fractions[std::size_t(k)], 1e-12);
    for (const Particle2D& p : phase.particles) EXPECT_EQ(p.phase, k);
    int counted = 0;
    for (int c : phase.histogram.counts) counted += c;
    EXPECT_EQ(std::size_t(counted), statisticalParticles(phase.particles).size());
  }
  EXPECT_EQ(total, stats.particles.size());
  // The nearest centre of each particle's colour and grain gives the same phases back, and so do
  // the colours alone (a solid made before phases read grain has K x 3 centres).
  const ParticlePhases again = nearestPhases(stats, stats.phaseCentres);
  const ParticlePhases byColour = nearestPhases(stats, stats.phaseCentres.colRange(0, 3).clone());
  for (std::size_t i = 0; i < stats.particles.size(); ++i) {
    EXPECT_EQ(again.phaseOf[i], stats.particles[i].phase);
    EXPECT_EQ(byColour.phaseOf[i], stats.particles[i].phase);
  }
}

// A third class of the small class's orange, told apart by its speckle alone (`truth`'s grain 0.1),
// is a phase of its own: the BIC finds three phases, two of them orange and some 4 L* units apart in
// grain, and each phase's particles are of one truth class (by the truth's particle under most of
// each photo particle): all of 60 pixels and more, and 90 % of all (a grain read on a section of
// some 30 pixels is noisy, and sections of 20 and less, too small to read one, take the phases'
// median and fall to either orange phase).
TEST(ParticlePhases, GrainTellsApartAClassOfTheSameColour) {
  ParticleTruthOptions options;
  options.dims = {320, 320, 48};
  options.classes[0].meanRadius = 5;
  options.classes[0].share = 0.45;
  options.classes[1].meanRadius = 10;
  ParticleClass grainy{7.5, 0.2, 0.3, options.classes[0].srgb};
  grainy.grain = 0.1;
  options.classes.insert(options.classes.begin() + 1, grainy);
  options.seed = 5;
  const ParticleTruth truth = makeParticleTruth(options);
  const ExemplarStats stats = analyzeExemplar(truth.photo, "truth", {});
  const ParticlePhases phases = classifyParticles(stats, kAutoPhases, 1);
  ASSERT_EQ(phases.centres.rows, 3);
  ASSERT_EQ(phases.centres.cols, 4);
  const Dims& dims = truth.volume.dims;
  std::vector<std::array<int, 3>> classesOfPhase(3, {0, 0, 0});
  std::vector<std::set<int>> readable(3);  // the classes of each phase's particles of 60 pixels or more
  for (std::size_t i = 0; i < stats.particles.size(); ++i) {
    const Particle2D& p = stats.particles[i];
    std::map<std::int32_t, int> votes;
    for (int y = 0; y < p.box.height; ++y)
      for (int x = 0; x < p.box.width; ++x)
        if (p.mask.at<std::uint8_t>(y, x))
          ++votes[truth.volume.particleId[dims.index(p.box.x + x, p.box.y + y, dims.z / 2)]];
    const std::int32_t id = std::max_element(votes.begin(), votes.end(), [](auto& a, auto& b) {
                              return a.second < b.second;
                            })->first;
    ASSERT_GT(id, 0);
    const int truthClass = truth.classOf[std::size_t(id - 1)];
    ++classesOfPhase[std::size_t(phases.phaseOf[i])][std::size_t(truthClass)];
    if (p.area >= 60) readable[std::size_t(phases.phaseOf[i])].insert(truthClass);
  }
  std::set<int> majorities;
  for (int k = 0; k < 3; ++k) {
    const auto& counts = classesOfPhase[std::size_t(k)];
    const auto top = std::max_element(counts.begin(), counts.end());
    majorities.insert(int(top - counts.begin()));
    EXPECT_GE(*top, 0.9 * (counts[0] + counts[1] + counts[2])) << "phase " << k;
    EXPECT_EQ(readable[std::size_t(k)].size(), 1u) << "phase " << k;
  }
  EXPECT_EQ(majorities.size(), 3u);
  // The two orange phases: one colour, grain apart.
  std::vector<int> orange;
  for (int k = 0; k < 3; ++k)
    if (phases.centres.at<float>(k, 2) > 0) orange.push_back(k);
  ASSERT_EQ(orange.size(), 2u);
  EXPECT_LT(
      cv::norm(phases.centres.row(orange[0]).colRange(0, 3), phases.centres.row(orange[1]).colRange(0, 3)),
      3.0);
  EXPECT_GT(std::abs(phases.centres.at<float>(orange[0], 3) - phases.centres.at<float>(orange[1], 3)), 3.0f);
}

// A label image sorts each particle by the value under most of it; too many values for the count
// asked for, or another size, is refused.
TEST(ParticlePhases, ALabelImageGivesEachParticleTheValueUnderMostOfIt) {
  const ExemplarStats stats = truthPhoto(false, 4);
  cv::Mat labels(stats.imageHeight, stats.imageWidth, CV_32FC3, cv::Scalar(0, 0, 0));
  for (const Particle2D& p : stats.particles)
    if (p.box.width > p.box.height) labels(p.box).setTo(cv::Scalar(1, 1, 1), p.mask);
  const ParticlePhases phases = particlePhasesOfLabels(stats, labels, "labels.png", 2);
  ASSERT_EQ(phases.centres.rows, 2);
  for (std::size_t i = 0; i < stats.particles.size(); ++i)
    EXPECT_EQ(phases.phaseOf[i], stats.particles[i].box.width > stats.particles[i].box.height ? 1 : 0);
  cv::Mat three = labels.clone();
  three(stats.particles[0].box).setTo(cv::Scalar(0.5, 0.5, 0.5), stats.particles[0].mask);
  EXPECT_THROW(particlePhasesOfLabels(stats, three, "labels.png", 2), InputError);
  EXPECT_EQ(particlePhasesOfLabels(stats, three, "labels.png").centres.rows, 3);
  EXPECT_THROW(particlePhasesOfLabels(stats, labels(cv::Rect(0, 0, 32, 32)).clone(), "labels.png"),
               InputError);
  EXPECT_THROW(classifyParticles(stats, 9, 1), OptionError);
  EXPECT_THROW(classifyParticles(stats, -1, 1), OptionError);
}

}  // namespace
}  // namespace solidtex
