#pragma once
#include <cstdint>
#include <memory>

namespace solidtex::synthesis::detail {

/// Settings of InvertedFileIndex. The k-means is kept short: analysis time, not the last percent
/// of recall, is the aim.
struct InvertedFileOptions {
  int lists = 0;             ///< k-means cells; 0 = 2 sqrt(count)
  int probes = 8;            ///< cells searched per point: those of the centroids nearest to it
  int trainingPerList = 32;  ///< k-means trains on at most this many points per cell
  int iterations = 10;       ///< k-means iterations
  int seed = 1234;           ///< k-means sampling and initialisation
};

/// The number of cells InvertedFileIndex uses for `count` points (options.lists, or its default).
int invertedFileLists(int count, const InvertedFileOptions& options);

/// Approximate nearest neighbours of each of `count` points of `dims` floats (row-major, point m at
/// points + m*dims) among all of them, for point sets where an exact kd-tree degrades towards
/// brute force (twenty dimensions, hundreds of thousands of points). An inverted file: FAISS's
/// k-means splits the points into cells, and each point is compared with the members of the cells
/// whose centroids are nearest to it; the points of one cell that probe the same cell are compared
/// with it together, as one matrix product. Parallel (TBB; FAISS's k-means on OpenMP with as many
/// threads); the answers do not depend on the thread count.
class InvertedFileIndex {
public:
  InvertedFileIndex(const float* points, int count, int dims, const InvertedFileOptions& options = {});
  ~InvertedFileIndex();
  InvertedFileIndex(const InvertedFileIndex&) = delete;
  InvertedFileIndex& operator=(const InvertedFileIndex&) = delete;

  /// The k nearest points found for every point (itself included), row by row: count*k ids and
  /// squared distances, sorted by increasing distance, ties by smaller id; -1 and infinity where the
  /// searched cells hold fewer than k points.
  void knnOfAllPoints(int k, std::int32_t* ids, float* squaredDistances) const;

  int count() const;
  int dims() const;
  int lists() const;
  int probes() const;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace solidtex::synthesis::detail
