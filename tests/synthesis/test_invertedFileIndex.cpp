#include <gtest/gtest.h>

#include <set>

#include <tbb/global_control.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/ExemplarPyramid.h"
#include "synthesis/detail/InvertedFileIndex.h"
#include "synthesis/detail/KdTree.h"
#include "synthesis/detail/SimilaritySets.h"

using namespace solidtex;
using namespace solidtex::synthesis::detail;

namespace {

/// The neighbourhoods of a real photo (pink marble, 128^2): 15625 of 4x4, reduced to 20 dimensions,
/// as the finest level of a synthesis from it.
ExemplarNeighborhoods marbleNeighborhoods() {
  cv::Mat bgr = cv::imread(std::string(SOLIDTEX_DATA_DIR) + "/continuous/pink_marble.png", cv::IMREAD_COLOR);
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  rgb.convertTo(rgb, CV_32FC3, 1.0 / 255);
  return buildExemplarNeighborhoods(toRgbImage(rgb), NeighborhoodShape{4}, 20);
}

struct Neighbours {
  std::vector<std::int32_t> ids;
  std::vector<float> squaredDistances;
  bool operator==(const Neighbours&) const = default;
};

Neighbours allNeighbours(const InvertedFileIndex& index, int k) {
  Neighbours all{std::vector<std::int32_t>(std::size_t(index.count()) * k),
                 std::vector<float>(std::size_t(index.count()) * k)};
  index.knnOfAllPoints(k, all.ids.data(), all.squaredDistances.data());
  return all;
}

/// Share of the exact k nearest (kd-tree) that the index's k nearest hold, over every `step`-th point.
double recall(const ExemplarNeighborhoods& n, const InvertedFileIndex& index, int k, int step) {
  const KdTree tree(n.reduced.data(), n.count(), n.reducedDims());
  const Neighbours all = allNeighbours(index, k);
  std::vector<std::int32_t> exact(k);
  std::vector<float> d(k);
  int found = 0, total = 0;
  for (int m = 0; m < n.count(); m += step) {
    tree.knn(n.reducedAt(m), k, exact.data(), d.data());
    const std::set<std::int32_t> got(all.ids.begin() + std::size_t(m) * k,
                                     all.ids.begin() + std::size_t(m + 1) * k);
    for (std::int32_t id : exact) found += got.count(id);
    total += k;
  }
  return double(found) / total;
}

}  // namespace

TEST(InvertedFileIndex, ProbingEveryCellIsExact) {
  const ExemplarNeighborhoods n = marbleNeighborhoods();
  InvertedFileOptions options;
  options.lists = 64;
  options.probes = 64;
  const InvertedFileIndex index(n.reduced.data(), n.count(), n.reducedDims(), options);
  EXPECT_EQ(index.lists(), 64);
  EXPECT_EQ(index.probes(), 64);
  const KdTree tree(n.reduced.data(), n.count(), n.reducedDims());
  const int k = 8;
  const Neighbours all = allNeighbours(index, k);
  std::vector<std::int32_t> exactIds(k);
  std::vector<float> exactD(k);
  for (int m = 0; m < n.count(); m += 97) {
    tree.knn(n.reducedAt(m), k, exactIds.data(), exactD.data());
    // Distances by a matrix product: |a|^2 + |b|^2 - 2ab rounds to about 1e-6 of the norms.
    for (int i = 0; i < k; ++i)
      EXPECT_NEAR(all.squaredDistances[std::size_t(m) * k + i], exactD[i], 1e-4f) << "m=" << m;
    EXPECT_EQ(all.ids[std::size_t(m) * k], m);
  }
}

// The default cells (2 sqrt(count) = 250), 8 probed per point, find most true neighbours of a
// photo's neighbourhoods: 0.93 of the 30 nearest here; the bound leaves room for other FAISS k-means.
TEST(InvertedFileIndex, DefaultsFindMostNearestNeighboursOfAPhoto) {
  const ExemplarNeighborhoods n = marbleNeighborhoods();
  const InvertedFileIndex index(n.reduced.data(), n.count(), n.reducedDims());
  EXPECT_EQ(index.lists(), invertedFileLists(n.count(), {}));
  EXPECT_EQ(index.lists(), 250);
  EXPECT_GT(recall(n, index, 30, 7), 0.88);
}

TEST(InvertedFileIndex, AnswersDoNotDependOnTheThreadCount) {
  const ExemplarNeighborhoods n = marbleNeighborhoods();
  const int k = 12;
  auto run = [&](int threads) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const InvertedFileIndex index(n.reduced.data(), n.count(), n.reducedDims());
    return allNeighbours(index, k);
  };
  EXPECT_EQ(run(1), run(2));
}

TEST(SimilaritySets, ApproximateSetsAreValidAndMostlyExact) {
  const ExemplarNeighborhoods n = marbleNeighborhoods();
  const SimilaritySets approximate = buildApproximateSimilaritySets(n, 5, 2);
  const SimilaritySets exact = buildSimilaritySets(n, 5, 2);
  EXPECT_EQ(approximate.lists, 250);
  EXPECT_EQ(approximate.probes, 8);
  EXPECT_EQ(exact.lists, 0);
  ASSERT_EQ(approximate.count(), exact.count());
  int same = 0;
  for (int m = 0; m < approximate.count(); ++m) {
    EXPECT_EQ(approximate.of(m)[0], m);
    const std::set<std::int32_t> exactSet(exact.of(m), exact.of(m) + exact.k);
    for (int q = 1; q < approximate.k; ++q) {
      const int o = approximate.of(m)[q];
      EXPECT_TRUE(std::abs(n.centreX(o) - n.centreX(m)) > 2 || std::abs(n.centreY(o) - n.centreY(m)) > 2);
      same += exactSet.count(o);
    }
  }
  EXPECT_GT(double(same) / (approximate.count() * (approximate.k - 1)), 0.9);  // 0.97 measured
}
