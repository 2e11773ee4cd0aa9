#include "synthesis/detail/KdTree.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <vector>

#include <nanoflann.hpp>

namespace solidtex::synthesis::detail {

namespace {

struct PointSet {
  const float* points;
  int count;
  int dims;
  std::size_t kdtree_get_point_count() const { return std::size_t(count); }
  float kdtree_get_pt(std::size_t idx, std::size_t dim) const { return points[idx * dims + dim]; }
  template <class Box>
  bool kdtree_get_bbox(Box&) const {
    return false;
  }
};

using Tree =
    nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, PointSet, float, std::uint32_t>,
                                        PointSet, -1, std::uint32_t>;

}  // namespace

struct KdTree::Impl {
  PointSet set;
  Tree tree;
  Impl(const float* points, int count, int dims)
      : set{points, count, dims}, tree(dims, set, nanoflann::KDTreeSingleIndexAdaptorParams(16)) {}
};

KdTree::KdTree(const float* points, int count, int dims)
    : impl_(std::make_unique<Impl>(points, count, dims)) {}
KdTree::~KdTree() = default;

int KdTree::count() const { return impl_->set.count; }
int KdTree::dims() const { return impl_->set.dims; }

void KdTree::knn(const float* query, int k, std::int32_t* ids, float* squaredDistances, float eps) const {
  k = std::min(k, impl_->set.count);
  std::vector<std::uint32_t> idx(k);
  std::vector<float> dist(k);
  nanoflann::KNNResultSet<float, std::uint32_t, std::uint32_t> result{static_cast<std::uint32_t>(k)};
  result.init(idx.data(), dist.data());
  impl_->tree.findNeighbors(result, query, nanoflann::SearchParams(32, eps));
  const int found = int(result.size());
  std::vector<int> order(found);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return dist[a] != dist[b] ? dist[a] < dist[b] : idx[a] < idx[b]; });
  for (int i = 0; i < found; ++i) {
    ids[i] = std::int32_t(idx[order[i]]);
    squaredDistances[i] = dist[order[i]];
  }
  for (int i = found; i < k; ++i) {
    ids[i] = -1;
    squaredDistances[i] = std::numeric_limits<float>::infinity();
  }
}

std::int32_t KdTree::nearest(const float* query, float* squaredDistance, float eps) const {
  std::int32_t id;
  float d;
  knn(query, 1, &id, &d, eps);
  if (squaredDistance) *squaredDistance = d;
  return id;
}

}  // namespace solidtex::synthesis::detail
