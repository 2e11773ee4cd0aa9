#include <gtest/gtest.h>

#include <limits>
#include <set>

#include "TestImages.h"
#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/ExemplarPyramid.h"
#include "synthesis/detail/SliceMatches.h"
#include "synthesis/detail/SliceNeighborhoods.h"
#include "synthesis/detail/upsample.h"

using namespace solidtex;
using namespace solidtex::synthesis::detail;

namespace {

/// A periodic n^3 volume whose every z-slice is the (n x n) exemplar.
WorkVolume stackedVolume(const RgbImage& ex) {
  WorkVolume v;
  v.n = ex.width;
  v.rgb.resize(v.count() * 3);
  v.source.resize(v.count());
  for (int z = 0; z < v.n; ++z)
    for (int y = 0; y < v.n; ++y)
      for (int x = 0; x < v.n; ++x) {
        std::copy(ex.at(x, y), ex.at(x, y) + 3, v.at(v.index(x, y, z)));
        v.source[v.index(x, y, z)] = y * ex.width + x;
      }
  return v;
}

}  // namespace

TEST(Neighborhoods, ExemplarNeighborhoodLayout) {
  const RgbImage ex = toRgbImage(test::randomImage(10, 9, 1));
  const NeighborhoodShape shape{4};
  EXPECT_EQ(shape.lo(), -2);
  EXPECT_EQ(shape.hi(), 1);
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(ex, shape, 48);
  EXPECT_EQ(n.cols, 7);
  EXPECT_EQ(n.rows, 6);
  const int m = n.indexOf(4, 5);
  EXPECT_EQ(n.centreX(m), 4);
  EXPECT_EQ(n.centreY(m), 5);
  // First component: pixel (centre + lo, centre + lo), red.
  EXPECT_EQ(n.full(0, m), ex.at(2, 3)[0]);
  EXPECT_EQ(n.full(shape.dims() - 1, m), ex.at(5, 6)[2]);
  EXPECT_EQ(n.clampedIndexOf(-5, 100), n.indexOf(2, 7));
}

TEST(Neighborhoods, CentreGridIdsRoundTrip) {
  const SliceCentreGrid grid{8, 2};
  EXPECT_EQ(grid.count(), 3u * 8 * 4 * 4);
  for (std::size_t id = 0; id < grid.count(); ++id) EXPECT_EQ(grid.id(grid.axisOf(id), grid.voxelOf(id)), id);
}

TEST(Neighborhoods, CoveringCentresSurroundTheVoxel) {
  const NeighborhoodShape shape{6};
  for (int step : {1, 2}) {
    const SliceCentreGrid grid{12, step};
    const std::array<int, 3> v{3, 0, 11};
    std::set<std::size_t> seen;
    forEachCoveringCentre(grid, shape, v, [&](std::size_t id, int i, int j) {
      const int axis = grid.axisOf(id);
      const SliceAxes s = sliceAxes(axis);
      auto c = grid.voxelOf(id);
      EXPECT_EQ(c[axis], v[axis]);
      EXPECT_EQ((c[s.u] + i + 12) % 12, v[s.u]);
      EXPECT_EQ((c[s.w] + j + 12) % 12, v[s.w]);
      seen.insert(id);
    });
    EXPECT_EQ(seen.size(), std::size_t(3 * (6 / step) * (6 / step)));
  }
}

TEST(Neighborhoods, ZSlicesOfAStackedVolumeMatchTheExemplarExactly) {
  const RgbImage ex = toRgbImage(test::smoothImage(16, 16));
  const WorkVolume v = stackedVolume(ex);
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(ex, NeighborhoodShape{4}, 48);
  std::vector<float> q(n.shape.dims());
  gatherSliceNeighborhood(v, 2, {6, 7, 3}, n.shape, q.data());
  for (int c = 0; c < n.shape.dims(); ++c) EXPECT_EQ(q[c], n.full(c, n.indexOf(6, 7)));

  SliceMatches matches(SliceCentreGrid{16, 2});
  std::vector<std::int64_t> hist;
  SearchSettings exhaustive;
  exhaustive.exhaustive = true;
  searchPhase(v, n, exhaustive, matches, hist);
  for (std::size_t id = 0; id < matches.grid.count(); ++id) {
    if (matches.grid.axisOf(id) != 2) continue;
    const auto c = matches.grid.voxelOf(id);
    if (c[0] < 2 || c[0] > 14 || c[1] < 2 || c[1] > 14) continue;  // wholly inside the exemplar
    EXPECT_EQ(matches.match[id], n.indexOf(c[0], c[1]));
    EXPECT_NEAR(matches.distance[id], 0.0f, 1e-6f);
  }
  std::int64_t total = 0;
  for (auto h : hist) total += h;
  EXPECT_EQ(total, std::int64_t(matches.grid.count()));
}

// Pan et al.'s eq. 3 features: a pixel's Haar coefficients, the same read from a slice as from the
// exemplar; and the transform is orthogonal up to 1/2, so a feature difference is half the colour one.
TEST(Neighborhoods, WaveletFeaturesAreTheBlocksHaarCoefficientsOnSlicesAndExemplar) {
  const RgbImage ex = toRgbImage(test::randomImage(16, 16, 4));
  const WorkVolume v = stackedVolume(ex);
  const NeighborhoodShape shape{4, true};
  EXPECT_EQ(shape.dims(), 4 * 4 * 12);
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(ex, shape, 20);
  EXPECT_EQ(n.cols, 16 - 5 + 1);  // one more pixel read beyond the neighbourhood
  std::vector<float> q(std::size_t(shape.dims()));
  gatherSliceNeighborhood(v, 2, {6, 7, 3}, shape, q.data());
  for (int c = 0; c < shape.dims(); ++c) EXPECT_FLOAT_EQ(q[std::size_t(c)], n.full(c, n.indexOf(6, 7)));
  // The first pixel (offset -2, -2) of the neighbourhood at (6, 7): the block at (4, 5).
  const float* p00 = ex.at(4, 5);
  const float *p10 = ex.at(5, 5), *p01 = ex.at(4, 6), *p11 = ex.at(5, 6);
  EXPECT_FLOAT_EQ(q[0], 0.25f * (p00[0] + p10[0] + p01[0] + p11[0]));
  EXPECT_FLOAT_EQ(q[3], 0.25f * (p00[0] - p10[0] + p01[0] - p11[0]));
  EXPECT_FLOAT_EQ(q[6], 0.25f * (p00[0] + p10[0] - p01[0] - p11[0]));
  EXPECT_FLOAT_EQ(q[9], 0.25f * (p00[0] - p10[0] - p01[0] + p11[0]));
  float features[12], other[12];
  float* out = features;
  writePixelFeatures(shape, ex.at(1, 1), ex.at(2, 1), ex.at(1, 2), ex.at(2, 2), out);
  out = other;
  writePixelFeatures(shape, ex.at(9, 3), ex.at(10, 3), ex.at(9, 4), ex.at(10, 4), out);
  double featureDistance = 0, colorDistance = 0;
  for (int k = 0; k < 12; ++k) featureDistance += double(features[k] - other[k]) * (features[k] - other[k]);
  for (const auto& [a, b] : {std::pair{ex.at(1, 1), ex.at(9, 3)}, std::pair{ex.at(2, 1), ex.at(10, 3)},
                             std::pair{ex.at(1, 2), ex.at(9, 4)}, std::pair{ex.at(2, 2), ex.at(10, 4)}})
    for (int c = 0; c < 3; ++c) colorDistance += double(a[c] - b[c]) * (a[c] - b[c]);
  EXPECT_NEAR(featureDistance, colorDistance / 4, 1e-6);
}

/// Eq. 5-6 scores of every exemplar neighbourhood for the slice neighbourhood `id`, by brute force:
/// the search must pick their minimum (ties: smaller id) whatever it prunes.
int bruteForceBest(const WorkVolume& v, const ExemplarNeighborhoods& n, const SearchSettings& s,
                   const SliceCentreGrid& grid, std::size_t id, const std::vector<std::int64_t>& hist,
                   std::int32_t previous) {
  std::vector<float> full(n.shape.dims());
  gatherSliceNeighborhood(v, grid.axisOf(id), grid.voxelOf(id), n.shape, full.data());
  const Eigen::VectorXf y =
      n.pca.basis.transpose() * (Eigen::Map<const Eigen::VectorXf>(full.data(), full.size()) - n.pca.mean);
  int best = -1;
  double bestScore = std::numeric_limits<double>::infinity();
  for (int m = 0; m < n.count(); ++m) {
    double d = 0;
    for (int c = 0; c < n.reducedDims(); ++c)
      d += double(y[c] - n.reducedAt(m)[c]) * double(y[c] - n.reducedAt(m)[c]);
    const double h = s.histogramScale * (double(hist[m]) - (m == previous ? 1 : 0));
    const double score =
        (1.0 + std::max(0.0, h - s.histogramScale * (*s.phi)[m])) * (d + s.distanceFloor * n.shape.dims());
    if (score < bestScore) bestScore = score, best = m;
  }
  return best;
}

TEST(Neighborhoods, PrunedExhaustiveSearchFindsTheBruteForceBest) {
  // A random volume and a non-trivial index histogram (second search): the early-stopping
  // distances and the walk over the sorted first coefficient must not change the winner.
  const RgbImage ex = toRgbImage(test::randomImage(16, 16, 9));
  const WorkVolume v = randomVolume(8, ex, 3);
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(ex, NeighborhoodShape{4}, 12);
  SliceMatches matches(SliceCentreGrid{8, 2});
  const std::vector<double> phi(n.count(), double(matches.grid.count()) / n.count());
  std::vector<std::int64_t> hist;
  SearchSettings s;
  s.exhaustive = true;
  s.phi = &phi;
  s.batches = 1;  // the histogram stays as it was before the search, as the reference assumes
  s.histogramScale = 8;
  searchPhase(v, n, s, matches, hist);
  const std::vector<std::int64_t> before = hist;
  const std::vector<std::int32_t> previous = matches.match;
  searchPhase(v, n, s, matches, hist);
  int agree = 0;
  for (std::size_t id = 0; id < matches.grid.count(); ++id)
    agree += matches.match[id] == bruteForceBest(v, n, s, matches.grid, id, before, previous[id]);
  // The reference sums in double, the search in float: allow a near-tie to go the other way.
  EXPECT_GE(agree, int(matches.grid.count()) - 2);
}

TEST(Neighborhoods, KCoherenceFindsTheCoherentMatch) {
  // With sources set, k-coherence candidates include the coherent shift: z-slices match exactly.
  const RgbImage ex = toRgbImage(test::randomImage(16, 16, 4));
  const WorkVolume v = stackedVolume(ex);
  const ExemplarNeighborhoods n = buildExemplarNeighborhoods(ex, NeighborhoodShape{4}, 20);
  const SimilaritySets sets = buildSimilaritySets(n, 3);
  SliceMatches matches(SliceCentreGrid{16, 2});
  std::vector<std::int64_t> hist;
  SearchSettings s;
  s.sets = &sets;
  const double energy = searchPhase(v, n, s, matches, hist);
  EXPECT_GT(energy, 0.0);
  for (std::size_t id = 0; id < matches.grid.count(); ++id) {
    const auto c = matches.grid.voxelOf(id);
    if (matches.grid.axisOf(id) == 2 && c[0] >= 2 && c[0] <= 14 && c[1] >= 2 && c[1] <= 14) {
      EXPECT_EQ(matches.match[id], n.indexOf(c[0], c[1]));
    }
  }
}

TEST(Neighborhoods, UpsamplingDoublesTheVolume) {
  const RgbImage fine = toRgbImage(test::smoothImage(16, 16));
  const RgbImage coarse = halve(fine);
  const WorkVolume v = randomVolume(4, coarse, 7);
  const WorkVolume up = upsampleSources(v, coarse.width, fine);
  EXPECT_EQ(up.n, 8);
  const int p = v.source[v.index(1, 2, 3)];
  EXPECT_EQ(up.source[up.index(3, 4, 6)], (2 * (p / 8)) * 16 + 2 * (p % 8) + 1);
  const WorkVolume smooth = upsampleColors(v);
  EXPECT_EQ(smooth.n, 8);
  for (float c : smooth.rgb) {
    EXPECT_GE(c, 0.0f);
    EXPECT_LE(c, 1.0f);
  }
}
