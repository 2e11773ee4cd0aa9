#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "phaseFixtures.h"
#include "validation/chordLengths.h"
#include "validation/linealPath.h"

namespace solidtex {
namespace {

// The share of chords of k voxels among those that fit in a line of n, when chords are
// exponential with `rate`: a chord of length l holds floor(l) or ceil(l) voxel centres (a tent
// around k), and lies wholly inside the line with probability proportional to n - 1 - l (Miles'
// length bias of chords the faces do not cut).
std::vector<double> expectedChordShares(double rate, int n) {
  std::vector<double> share(std::size_t(n), 0.0);
  double total = 0;
  for (int k = 1; k < n - 1; ++k) {
    for (int step = -999; step < 1000; ++step) {
      const double l = k + step / 1000.0;
      share[std::size_t(k)] += rate * std::exp(-rate * l) * (1 - std::abs(l - k)) * (n - 1 - l) / 1000.0;
    }
    total += share[std::size_t(k)];
  }
  for (double& s : share) s /= total;
  return share;
}

// In a Boolean model of balls of radius R and intensity lambda, a segment of length l lies in the
// matrix with probability p exp(-lambda pi R^2 l): the matrix's lineal path, and its chords are
// exponential with mean 1 / (lambda pi R^2).
TEST(ChordLengths, MatrixOfTheBooleanBallModelIsExponential) {
  double intensity = 0;
  const double R = 5, p = 0.5;
  const int n = 96;
  const PhaseField matrix = testing::booleanBallsMatrix(n, R, p, 3, &intensity);
  const double rate = intensity * std::numbers::pi * R * R;
  const std::vector<double> expected = expectedChordShares(rate, n);
  double expectedMean = 0;
  for (int k = 1; k < n; ++k) expectedMean += k * expected[std::size_t(k)];
  const ChordLengths chords = chordLengths(matrix);
  for (const auto& counts : chords.counts) {
    // A few thousand chords per axis: their mean is within about 3 % of its expectation.
    EXPECT_NEAR(meanChord(counts), expectedMean, 0.04 * expectedMean);
    const std::vector<double> histogram = chordHistogram(counts, 2, 10);
    for (int b = 0; b < 9; ++b)
      EXPECT_NEAR(histogram[std::size_t(b)],
                  expected[std::size_t(2 * b + 1)] + expected[std::size_t(2 * b + 2)], 0.02)
          << b;
  }
  const auto lineal = linealPath(matrix, 20);
  const double phi = matrix.fraction();
  for (const auto& axis : lineal) {
    ASSERT_EQ(axis.size(), 21u);
    EXPECT_NEAR(axis[0], phi, 1e-12);
    for (int r = 1; r <= 20; ++r) EXPECT_NEAR(axis[std::size_t(r)], phi * std::exp(-rate * r), 0.015) << r;
  }
}

TEST(ChordLengths, LeavesOutChordsTheFacesCutUnlessAsked) {
  const PhaseField row =
      testing::fieldWhere({10, 1, 1}, [](double x, double, double) { return x < 2 || (x > 3 && x < 7); });
  EXPECT_EQ(chordLengths(row).counts[0], (std::vector<std::size_t>{0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(chordLengths(row, true).counts[0], (std::vector<std::size_t>{0, 0, 1, 1, 0, 0, 0, 0, 0, 0, 0}));
  EXPECT_TRUE(chordLengths(row).counts[1].empty());
  const auto lineal = linealPath(row, 3);
  EXPECT_NEAR(lineal[0][0], 0.5, 1e-12);
  EXPECT_NEAR(lineal[0][1], 3.0 / 9, 1e-12);  // segments 0-1, 4-5, 5-6 of 9
  EXPECT_NEAR(lineal[0][2], 1.0 / 8, 1e-12);
  EXPECT_NEAR(lineal[0][3], 0.0, 1e-12);
}

}  // namespace
}  // namespace solidtex
