#include "synthesis/detail/InvertedFileIndex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <faiss/Clustering.h>
#include <faiss/IndexFlat.h>
#include <omp.h>
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#include <Eigen/Core>

namespace solidtex::synthesis::detail {

namespace {

using Id = faiss::Index::idx_t;
using ColumnMatrix = Eigen::Map<const Eigen::MatrixXf>;  // one point per column
using RowMatrix = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/// FAISS parallelises its k-means with OpenMP: give it the threads TBB may use (the --threads limit).
void limitOpenMpToTbb() {
  omp_set_num_threads(int(tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
}

/// A running list of the k nearest candidates, sorted by (distance, id).
template <class IdType>
void offer(float d, IdType id, int k, int& found, float* distances, IdType* ids) {
  auto before = [](float da, IdType ia, float db, IdType ib) { return da != db ? da < db : ia < ib; };
  if (found == k && !before(d, id, distances[k - 1], ids[k - 1])) return;
  int i = found < k ? found++ : k - 1;
  for (; i > 0 && before(d, id, distances[i - 1], ids[i - 1]); --i) {
    distances[i] = distances[i - 1];
    ids[i] = ids[i - 1];
  }
  distances[i] = d;
  ids[i] = id;
}

/// Squared distances between the columns of a and of b by one matrix product: |a|^2 + |b|^2 - 2ab.
RowMatrix pairwiseSquaredDistances(const ColumnMatrix& a, const Eigen::VectorXf& aNorms,
                                   const ColumnMatrix& b, const Eigen::VectorXf& bNorms) {
  RowMatrix d = -2.0f * (a.transpose() * b);
  d.colwise() += aNorms;
  d.rowwise() += bNorms.transpose();
  return d.cwiseMax(0.0f);
}

/// IndexFlatL2 whose search is a blocked matrix product (Eigen) in parallel (TBB): FAISS's k-means
/// assigns points through it. Debian's FAISS computes these distances one pair at a time or through
/// the reference BLAS, both slower.
struct ProductFlatL2 : faiss::IndexFlatL2 {
  using faiss::IndexFlatL2::IndexFlatL2;

  void search(Id n, const float* x, Id k, float* distances, Id* labels,
              const faiss::SearchParameters* = nullptr) const override {
    const ColumnMatrix centroids(get_xb(), d, ntotal);
    const Eigen::VectorXf centroidNorms = centroids.colwise().squaredNorm().transpose();
    constexpr Id block = 256;
    tbb::parallel_for(Id(0), (n + block - 1) / block, [&](Id b) {
      const Id first = b * block, count = std::min(block, n - first);
      const ColumnMatrix queries(x + first * d, d, count);
      const RowMatrix all = pairwiseSquaredDistances(queries, queries.colwise().squaredNorm().transpose(),
                                                     centroids, centroidNorms);
      for (Id q = 0; q < count; ++q) {
        float* outDistances = distances + (first + q) * k;
        Id* outLabels = labels + (first + q) * k;
        int found = 0;
        for (Id c = 0; c < ntotal; ++c) offer(all(q, c), c, int(k), found, outDistances, outLabels);
        std::fill(outDistances + found, outDistances + k, std::numeric_limits<float>::infinity());
        std::fill(outLabels + found, outLabels + k, Id(-1));
      }
    });
  }
};

}  // namespace

int invertedFileLists(int count, const InvertedFileOptions& options) {
  const int lists = options.lists > 0 ? options.lists : int(std::lround(2 * std::sqrt(double(count))));
  return std::clamp(lists, 1, std::max(1, count));
}

struct InvertedFileIndex::Impl {
  int count = 0, dims = 0, lists = 0, probes = 0;
  std::vector<Id> probed;      ///< count x probes: each point's nearest cells, its own first
  std::vector<int> cellStart;  ///< lists + 1: cell c holds sorted positions cellStart[c]..cellStart[c+1]
  std::vector<std::int32_t> members;  ///< point ids in cell order (ascending within a cell)
  std::vector<float> sorted;          ///< the points in cell order, dims floats each
  Eigen::VectorXf norms;              ///< their squared norms

  void buildCells(const float* points) {
    cellStart.assign(lists + 1, 0);
    for (int m = 0; m < count; ++m) ++cellStart[probed[std::size_t(m) * probes] + 1];
    for (int c = 0; c < lists; ++c) cellStart[c + 1] += cellStart[c];
    std::vector<int> next(cellStart.begin(), cellStart.end() - 1);
    members.resize(count);
    for (int m = 0; m < count; ++m) members[next[probed[std::size_t(m) * probes]]++] = m;
    sorted.resize(std::size_t(count) * dims);
    for (int i = 0; i < count; ++i)
      std::copy_n(points + std::size_t(members[i]) * dims, dims, sorted.begin() + std::size_t(i) * dims);
    norms = ColumnMatrix(sorted.data(), dims, count).colwise().squaredNorm().transpose();
  }

  ColumnMatrix cellPoints(int first, int n) const {
    return {sorted.data() + std::size_t(first) * dims, dims, n};
  }
};

InvertedFileIndex::InvertedFileIndex(const float* points, int count, int dims,
                                     const InvertedFileOptions& options)
    : impl_(std::make_unique<Impl>()) {
  Impl& im = *impl_;
  im.count = count;
  im.dims = dims;
  im.lists = invertedFileLists(count, options);
  im.probes = std::clamp(options.probes, 1, im.lists);
  limitOpenMpToTbb();
  faiss::ClusteringParameters parameters;
  parameters.niter = options.iterations;
  parameters.max_points_per_centroid = options.trainingPerList;
  parameters.min_points_per_centroid = 1;  // a short k-means on few points is intended: no warning
  parameters.seed = options.seed;
  faiss::Clustering kmeans(dims, im.lists, parameters);
  ProductFlatL2 centroids(dims);
  kmeans.train(count, points, centroids);  // leaves the centroids in `centroids`
  im.probed.resize(std::size_t(count) * im.probes);
  std::vector<float> cellDistances(im.probed.size());
  centroids.search(count, points, im.probes, cellDistances.data(), im.probed.data());
  im.buildCells(points);
}

InvertedFileIndex::~InvertedFileIndex() = default;

int InvertedFileIndex::count() const { return impl_->count; }
int InvertedFileIndex::dims() const { return impl_->dims; }
int InvertedFileIndex::lists() const { return impl_->lists; }
int InvertedFileIndex::probes() const { return impl_->probes; }

void InvertedFileIndex::knnOfAllPoints(int k, std::int32_t* ids, float* squaredDistances) const {
  const Impl& im = *impl_;
  constexpr int block = 256;  // queries of one cell searched together
  tbb::parallel_for(0, im.lists, [&](int cell) {
    std::vector<std::pair<Id, int>> visits;  // (probed cell, query of the block), by cell
    Eigen::MatrixXf queries(im.dims, block);
    Eigen::VectorXf queryNorms(block);
    for (int q0 = im.cellStart[cell]; q0 < im.cellStart[cell + 1]; q0 += block) {
      const int nq = std::min(block, im.cellStart[cell + 1] - q0);
      visits.clear();
      for (int q = 0; q < nq; ++q) {
        const Id* p = im.probed.data() + std::size_t(im.members[q0 + q]) * im.probes;
        for (int i = 0; i < im.probes; ++i) visits.emplace_back(p[i], q);
      }
      std::sort(visits.begin(), visits.end());
      std::vector<int> found(nq, 0);
      for (std::size_t v0 = 0; v0 < visits.size();) {
        const Id c = visits[v0].first;
        std::size_t v1 = v0;
        for (; v1 < visits.size() && visits[v1].first == c; ++v1) {
          queries.col(Eigen::Index(v1 - v0)) = im.cellPoints(q0 + visits[v1].second, 1);
          queryNorms[Eigen::Index(v1 - v0)] = im.norms[q0 + visits[v1].second];
        }
        const int p0 = im.cellStart[c], np = im.cellStart[c + 1] - p0, ng = int(v1 - v0);
        const ColumnMatrix group(queries.data(), im.dims, ng);
        const RowMatrix d = pairwiseSquaredDistances(group, queryNorms.head(ng), im.cellPoints(p0, np),
                                                     im.norms.segment(p0, np));
        for (int g = 0; g < ng; ++g) {
          const int q = visits[v0 + g].second;
          const std::size_t row = std::size_t(im.members[q0 + q]) * k;
          for (int p = 0; p < np; ++p)
            offer(d(g, p), im.members[p0 + p], k, found[q], squaredDistances + row, ids + row);
        }
        v0 = v1;
      }
      for (int q = 0; q < nq; ++q) {
        const std::size_t row = std::size_t(im.members[q0 + q]) * k;
        std::fill(squaredDistances + row + found[q], squaredDistances + row + k,
                  std::numeric_limits<float>::infinity());
        std::fill(ids + row + found[q], ids + row + k, -1);
      }
    }
  });
}

}  // namespace solidtex::synthesis::detail
