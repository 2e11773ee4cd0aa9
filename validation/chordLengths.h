#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "validation/PhaseField.h"

namespace solidtex {

/// The chords of a phase along each axis (the runs of its voxels on the axis lines), counted by
/// length: counts[a][l] is the number of chords of l voxels along axis a (counts[a][0] = 0). Empty
/// for an axis the field is flat in.
struct ChordLengths {
  std::array<std::vector<std::size_t>, 3> counts;
};

/// Chords of `phase`; keepCut: also the runs that the field's faces cut, which are left out by
/// default (their length is unknown, as PoreSpy's trim_edges).
ChordLengths chordLengths(const PhaseField& phase, bool keepCut = false);

/// The mean length of the chords counted, in voxels; 0 without any.
double meanChord(const std::vector<std::size_t>& counts);

/// The share of chords in `bins` bins of `width` voxels: [1, width], [width+1, 2 width], ...; the
/// last bin holds all longer chords.
std::vector<double> chordHistogram(const std::vector<std::size_t>& counts, int width, int bins);

}  // namespace solidtex
