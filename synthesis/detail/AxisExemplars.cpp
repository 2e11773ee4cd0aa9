#include "synthesis/detail/AxisExemplars.h"

#include <algorithm>

namespace solidtex::synthesis::detail {

namespace {

/// The neighbourhoods [first, end) alone, numbered from 0, with what the similarity search reads.
ExemplarNeighborhoods rowsOf(const ExemplarNeighborhoods& n, int first, int end) {
  ExemplarNeighborhoods part;
  part.shape = n.shape;
  part.exemplarWidth = n.exemplarWidth;
  part.exemplarHeight = n.exemplarHeight;
  part.x0 = n.x0;
  part.y0 = n.centreY(first);
  part.cols = n.cols;
  part.rows = (end - first) / n.cols;
  part.pca = n.pca;
  part.reduced.assign(n.reducedAt(first), n.reducedAt(first) + std::size_t(end - first) * n.reducedDims());
  return part;
}

}  // namespace

AxisExemplars axisExemplarsOf(const ExemplarNeighborhoods& n, int planeHeight) {
  AxisExemplars axes;
  axes.planeHeight = planeHeight;
  for (int axis = 0; axis < 3; ++axis) {
    if (planeHeight == 0) {
      axes.first[axis] = 0, axes.end[axis] = n.count();
      continue;
    }
    // Centre row r (y = y0 + r) lies wholly inside plane `axis` for r in [axis H, axis H + H - extent].
    const int rows = std::max(0, planeHeight - n.shape.extent() + 1);
    axes.first[axis] = axis * planeHeight * n.cols;
    axes.end[axis] = axes.first[axis] + rows * n.cols;
  }
  return axes;
}

SimilaritySets buildPlaneSimilaritySets(const ExemplarNeighborhoods& n, const AxisExemplars& axes, int k,
                                        int minSeparation, bool approximate) {
  auto build = [&](const ExemplarNeighborhoods& part) {
    return approximate ? buildApproximateSimilaritySets(part, k, minSeparation)
                       : buildSimilaritySets(part, k, minSeparation);
  };
  if (axes.planeHeight == 0) return build(n);
  SimilaritySets sets;
  sets.k = std::clamp(k, 1, std::max(1, axes.count(0)));  // the planes hold equally many
  sets.ids.resize(std::size_t(n.count()) * sets.k);
  for (int m = 0; m < n.count(); ++m) std::fill_n(sets.ids.begin() + std::ptrdiff_t(m) * sets.k, sets.k, m);
  for (int axis = 0; axis < 3; ++axis) {
    const SimilaritySets part = build(rowsOf(n, axes.first[axis], axes.end[axis]));
    for (int m = 0; m < part.count(); ++m)
      for (int i = 0; i < sets.k; ++i)
        sets.ids[std::size_t(axes.first[axis] + m) * sets.k + i] = axes.first[axis] + part.of(m)[i];
    sets.lists = part.lists, sets.probes = part.probes;
  }
  return sets;
}

}  // namespace solidtex::synthesis::detail
