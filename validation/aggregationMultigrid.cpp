#include "validation/aggregationMultigrid.h"

#include <algorithm>
#include <deque>
#include <functional>
#include <numeric>
#include <stdexcept>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/SparseCholesky>

namespace solidtex {
namespace {

using Matrix = AggregationMultigrid::Matrix;
using Entry = std::pair<int, double>;

// Rows smoothed as one Gauss-Seidel block: fixed, so the sweep is the same at any thread count.
constexpr int kSmoothingChunk = 8192;
// At or below this many unknowns the level is solved directly.
constexpr int kDirectRows = 4000;
// Aggregates that hardly merge anything (a level of isolated chains) end the hierarchy there.
constexpr double kStalledShare = 0.8;
// A piecewise-constant coarse correction undershoots smooth error; scaling it up (Vanek, Mandel and
// Brezina 1996; Notay's AGMG) took CG from 60 to 41 iterations on touching particles at 256^3.
constexpr double kCoarseCorrectionWeight = 1.5;

// Rows of a compressed row-major matrix, owned or not.
struct RowView {
  int rows = 0;
  const int* outer = nullptr;
  const int* inner = nullptr;
  const double* value = nullptr;

  template <typename M>
  static RowView of(const M& m) {
    return {int(m.rows()), m.outerIndexPtr(), m.innerIndexPtr(), m.valuePtr()};
  }
};

void forRows(int rows, int grain, const std::function<void(int, int)>& body) {
  tbb::parallel_for(tbb::blocked_range<int>(0, rows, grain),
                    [&](const tbb::blocked_range<int>& r) { body(r.begin(), r.end()); });
}

int findRoot(std::vector<int>& parent, int i) {
  while (parent[std::size_t(i)] != i)
    i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
  return i;
}

Voxel blockOf(const Voxel& v) { return {v.x >> 1, v.y >> 1, v.z >> 1}; }

}  // namespace

struct AggregationMultigrid::Hierarchy {
  struct Level {
    RowView a;
    Matrix owned;
    Eigen::VectorXd inverseDiagonal;
    std::vector<int> coarse;  // per row: its aggregate on the next level
    std::unique_ptr<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> direct;
    mutable Eigen::VectorXd b, x, residual, previous;
  };
  std::deque<Level> levels;  // a deque: rows of coarse levels are read through pointers into them

  void smooth(const Level& level, bool forward) const;
  void cycle(std::size_t l) const;
};

namespace {

// Aggregates of one level: each row's 2x2x2 block of voxels, split into the parts the matrix joins
// within the block; numbered in the order of their first row.
std::vector<int> aggregates(const RowView& a, const std::vector<Voxel>& voxels, int& count) {
  std::vector<int> parent(std::size_t(a.rows));
  std::iota(parent.begin(), parent.end(), 0);
  for (int i = 0; i < a.rows; ++i)
    for (int k = a.outer[i]; k < a.outer[i + 1]; ++k) {
      const int j = a.inner[k];
      if (j == i || a.value[k] == 0 || !(blockOf(voxels[std::size_t(i)]) == blockOf(voxels[std::size_t(j)])))
        continue;
      const int ri = findRoot(parent, i), rj = findRoot(parent, j);
      if (ri != rj) parent[std::size_t(std::max(ri, rj))] = std::min(ri, rj);
    }
  std::vector<int> id(std::size_t(a.rows), -1), coarse(std::size_t(a.rows));
  count = 0;
  for (int i = 0; i < a.rows; ++i) {
    int& root = id[std::size_t(findRoot(parent, i))];
    if (root < 0) root = count++;
    coarse[std::size_t(i)] = root;
  }
  return coarse;
}

// P^T A P for the piecewise-constant prolongation P of `coarse`, rows summed in a fixed order.
Matrix galerkinProduct(const RowView& a, const std::vector<int>& coarse, int coarseRows) {
  std::vector<int> memberStart(std::size_t(coarseRows) + 1, 0), members(std::size_t(a.rows));
  for (int c : coarse) ++memberStart[std::size_t(c) + 1];
  std::partial_sum(memberStart.begin(), memberStart.end(), memberStart.begin());
  std::vector<int> fill(memberStart.begin(), memberStart.end() - 1);
  for (int i = 0; i < a.rows; ++i) members[std::size_t(fill[std::size_t(coarse[std::size_t(i)])]++)] = i;

  const auto coarseRow = [&](int row, std::vector<Entry>& entries) {
    entries.clear();
    for (int m = memberStart[std::size_t(row)]; m < memberStart[std::size_t(row) + 1]; ++m) {
      const int i = members[std::size_t(m)];
      for (int k = a.outer[i]; k < a.outer[i + 1]; ++k) {
        const int col = coarse[std::size_t(a.inner[k])];
        auto at =
            std::find_if(entries.begin(), entries.end(), [&](const Entry& e) { return e.first == col; });
        if (at == entries.end())
          entries.emplace_back(col, a.value[k]);
        else
          at->second += a.value[k];
      }
    }
    std::sort(entries.begin(), entries.end());
  };
  Matrix out(coarseRows, coarseRows);
  int* start = out.outerIndexPtr();
  start[0] = 0;
  forRows(coarseRows, 1024, [&](int begin, int end) {
    std::vector<Entry> entries;
    for (int row = begin; row < end; ++row) coarseRow(row, entries), start[row + 1] = int(entries.size());
  });
  std::partial_sum(start, start + coarseRows + 1, start);
  out.resizeNonZeros(start[coarseRows]);
  forRows(coarseRows, 1024, [&](int begin, int end) {
    std::vector<Entry> entries;
    for (int row = begin; row < end; ++row) {
      coarseRow(row, entries);
      for (std::size_t e = 0; e < entries.size(); ++e) {
        out.innerIndexPtr()[start[row] + int(e)] = entries[e].first;
        out.valuePtr()[start[row] + int(e)] = entries[e].second;
      }
    }
  });
  return out;
}

}  // namespace

// Gauss-Seidel within chunks of rows, Jacobi between them: a chunk reads other chunks' values from
// before the sweep. Forward before the coarse correction and backward after keeps the cycle
// symmetric, as conjugate gradients need.
void AggregationMultigrid::Hierarchy::smooth(const Level& level, bool forward) const {
  const RowView& a = level.a;
  level.previous = level.x;
  const int chunks = (a.rows + kSmoothingChunk - 1) / kSmoothingChunk;
  forRows(chunks, 1, [&](int chunkBegin, int chunkEnd) {
    for (int chunk = chunkBegin; chunk < chunkEnd; ++chunk) {
      const int first = chunk * kSmoothingChunk, last = std::min(a.rows, first + kSmoothingChunk);
      for (int n = 0; n < last - first; ++n) {
        const int i = forward ? first + n : last - 1 - n;
        double sum = level.b[i];
        for (int k = a.outer[i]; k < a.outer[i + 1]; ++k) {
          const int j = a.inner[k];
          if (j == i) continue;
          sum -= a.value[k] * (j >= first && j < last ? level.x[j] : level.previous[j]);
        }
        level.x[i] = sum * level.inverseDiagonal[i];
      }
    }
  });
}

void AggregationMultigrid::Hierarchy::cycle(std::size_t l) const {
  const Level& level = levels[l];
  if (level.direct) {
    level.x = level.direct->solve(level.b);
    return;
  }
  const RowView& a = level.a;
  level.x.setZero(a.rows);
  smooth(level, true);
  forRows(a.rows, 4096, [&](int begin, int end) {
    for (int i = begin; i < end; ++i) {
      double r = level.b[i];
      for (int k = a.outer[i]; k < a.outer[i + 1]; ++k) r -= a.value[k] * level.x[a.inner[k]];
      level.residual[i] = r;
    }
  });
  const Level& next = levels[l + 1];
  next.b.setZero(next.a.rows);
  for (int i = 0; i < a.rows; ++i) next.b[level.coarse[std::size_t(i)]] += level.residual[i];
  cycle(l + 1);
  forRows(a.rows, 4096, [&](int begin, int end) {
    for (int i = begin; i < end; ++i)
      level.x[i] += kCoarseCorrectionWeight * next.x[level.coarse[std::size_t(i)]];
  });
  smooth(level, false);
}

AggregationMultigrid::AggregationMultigrid() = default;
AggregationMultigrid::~AggregationMultigrid() = default;
AggregationMultigrid::AggregationMultigrid(AggregationMultigrid&&) noexcept = default;
AggregationMultigrid& AggregationMultigrid::operator=(AggregationMultigrid&&) noexcept = default;

void AggregationMultigrid::setVoxels(std::vector<Voxel> voxels) { voxels_ = std::move(voxels); }

int AggregationMultigrid::levels() const { return hierarchy_ ? int(hierarchy_->levels.size()) : 0; }

void AggregationMultigrid::build(const Eigen::Map<const Matrix>& a) {
  if (voxels_.size() != std::size_t(a.rows()))
    throw std::invalid_argument("AggregationMultigrid: setVoxels needs one voxel per row of the matrix");
  hierarchy_ = std::make_unique<Hierarchy>();
  auto& levels = hierarchy_->levels;
  std::vector<Voxel> voxels = std::move(voxels_);
  voxels_ = {};
  levels.emplace_back().a = RowView::of(a);
  while (true) {
    Hierarchy::Level& level = levels.back();
    const RowView view = level.a;
    level.inverseDiagonal.resize(view.rows);
    level.residual.resize(view.rows);
    for (int i = 0; i < view.rows; ++i)
      for (int k = view.outer[i]; k < view.outer[i + 1]; ++k)
        if (view.inner[k] == i) level.inverseDiagonal[i] = 1.0 / view.value[k];
    int coarseRows = 0;
    if (view.rows > kDirectRows) level.coarse = aggregates(view, voxels, coarseRows);
    if (view.rows <= kDirectRows || coarseRows > kStalledShare * view.rows) {
      level.coarse.clear();
      level.direct = std::make_unique<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>(
          Eigen::SparseMatrix<double>(Eigen::Map<const Matrix>(view.rows, view.rows, view.outer[view.rows],
                                                               view.outer, view.inner, view.value)));
      break;
    }
    std::vector<Voxel> coarseVoxels(static_cast<std::size_t>(coarseRows));
    for (int i = 0; i < view.rows; ++i)
      coarseVoxels[std::size_t(level.coarse[std::size_t(i)])] = blockOf(voxels[std::size_t(i)]);
    voxels = std::move(coarseVoxels);
    Matrix product = galerkinProduct(view, level.coarse, coarseRows);
    Hierarchy::Level& next = levels.emplace_back();
    next.owned = std::move(product);
    next.a = RowView::of(next.owned);
  }
}

Eigen::VectorXd AggregationMultigrid::cycle(const Eigen::VectorXd& b) const {
  const auto& first = hierarchy_->levels.front();
  first.b = b;
  hierarchy_->cycle(0);
  return first.x;
}

}  // namespace solidtex
