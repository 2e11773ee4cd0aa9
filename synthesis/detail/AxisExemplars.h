#pragma once
#include <array>
#include <cstdint>

#include "synthesis/detail/ExemplarNeighborhoods.h"
#include "synthesis/detail/SimilaritySets.h"

namespace solidtex::synthesis::detail {

/// Which exemplar neighbourhoods the slices orthogonal to each axis match. With one exemplar, all of
/// them. With one exemplar per plane (Kopf et al.'s and Chen and Wang's three-exemplar form), the
/// three are stacked into one tall image, yz (x slices) on top, then xz, then xy, each `planeHeight`
/// rows; a source pixel is then a pixel of the tall image, so sources, colours and upsampling need
/// no other change, and each axis matches only the neighbourhoods lying wholly inside its plane.
struct AxisExemplars {
  int planeHeight = 0;                ///< rows of one plane's exemplar; 0 = one exemplar for all axes
  std::array<int, 3> first{}, end{};  ///< neighbourhood ids [first, end) each axis matches

  int count(int axis) const { return end[axis] - first[axis]; }
  bool contains(int axis, int m) const { return m >= first[axis] && m < end[axis]; }
  /// Pixel row y of the tall image moved to the same row of `axis`'s plane.
  int rowIn(int axis, int y) const { return planeHeight ? axis * planeHeight + y % planeHeight : y; }
};

/// All neighbourhoods for every axis (one exemplar), or each plane's rows of a tall image of three
/// planes of `planeHeight` rows (planeHeight > 0).
AxisExemplars axisExemplarsOf(const ExemplarNeighborhoods& neighborhoods, int planeHeight);

/// Similarity sets whose members lie in the same plane as their neighbourhood: each plane's sets
/// built alone (exactly or approximately), the ids of rows between planes holding only themselves.
SimilaritySets buildPlaneSimilaritySets(const ExemplarNeighborhoods& neighborhoods, const AxisExemplars& axes,
                                        int k, int minSeparation, bool approximate);

}  // namespace solidtex::synthesis::detail
