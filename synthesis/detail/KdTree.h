#pragma once
#include <cstdint>
#include <memory>

namespace solidtex::synthesis::detail {

/// Exact (or eps-approximate) nearest neighbours among `count` points of `dims` floats stored
/// row-major (point m at points + m*dims); the caller keeps the points alive. Built once,
/// read-only afterwards: queries are thread-safe. Wraps nanoflann.
class KdTree {
public:
  KdTree(const float* points, int count, int dims);
  ~KdTree();
  KdTree(const KdTree&) = delete;
  KdTree& operator=(const KdTree&) = delete;

  /// The k nearest points to `query` (k <= count), sorted by increasing squared distance, ties by
  /// smaller id. Writes k ids and k squared distances. eps > 0 allows (1+eps)-approximate answers.
  void knn(const float* query, int k, std::int32_t* ids, float* squaredDistances, float eps = 0) const;

  /// The nearest point; writes its squared distance when `squaredDistance` is not null.
  std::int32_t nearest(const float* query, float* squaredDistance = nullptr, float eps = 0) const;

  int count() const;
  int dims() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace solidtex::synthesis::detail
