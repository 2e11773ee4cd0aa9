#pragma once
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace solidtex {

/// Per column of `queries`, the distance to the nearest column of `targets` (exact search), as the RMS
/// difference per component so that patches of every size compare.
std::vector<double> nearestPatchDistances(const Eigen::MatrixXf& queries, const Eigen::MatrixXf& targets);

/// Mean of nearestPatchDistances: Simakov et al.'s coherence term when the queries are the synthesised
/// patches and the targets the exemplar's, their completeness term the other way round.
double meanNearestPatchDistance(const Eigen::MatrixXf& queries, const Eigen::MatrixXf& targets);

/// Sliced Wasserstein-1 distance between the distributions of the columns of `a` and `b` (equal
/// counts): the mean over `directions` random unit directions of the 1D Wasserstein-1 distance
/// between the projections. Same seed, same directions.
double slicedWasserstein(const Eigen::MatrixXf& a, const Eigen::MatrixXf& b, int directions,
                         std::uint64_t seed);

}  // namespace solidtex
