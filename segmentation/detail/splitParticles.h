#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Labels the particles of a CV_8U mask (non-zero = particle): CV_32S, 0 on background, 1..N in
// raster order of each particle's first pixel. Without `split`, a particle is an 8-connected
// component. With it, touching particles are cut apart: the Euclidean distance transform has one
// peak per particle, and a flood from the peaks downwards keeps two peaks apart where the neck
// between them is narrower than the smaller body (a depth relative to the peak, so the rule is
// the same at every scale, and an elongated particle, whose ridge has no deep saddle, stays
// whole); then the cuts that leave less convex pieces than the whole are undone
// (mergeWhereMoreConvex).
cv::Mat labelParticles(const cv::Mat& mask, bool split);

}  // namespace solidtex::segmentation::detail
