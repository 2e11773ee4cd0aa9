#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Redraws the outlines of the particles of a blurred photo (`lab`, CV_32FC3 CIE L*a*b*) half-way
// up their edges: where the colour distance from the background is half-way between the
// background's and each particle's own plateau, after a Gaussian of the photo's measured blur
// (`blur`, pixels) has taken the noise off the shallow edges. On a blurred, noisy photo the
// watershed's border wanders along each edge's wide ramp with the noise, and the outlines come out
// ragged. The colours are smoothed before their distance is taken, so the noise does not raise the
// background's distance (a length of a noisy vector) and push the outlines in. `particles` (CV_8U,
// non-zero on particles) gives the particles to redraw; each may grow by ceil(2 blur) steps of a
// 3x3 dilation or shrink, and particles that were apart stay apart. Returns the CV_8U mask, 255 on particles,
// or an empty one where the photo does not fit this model of a blurred step from a plain background: where
// the background's smoothed distance wanders (its 90th percentile above its median) by more than
// `maxBackgroundSpread` of the particles' typical contrast (a grainy matrix, gaps in shadow).
cv::Mat halfMaximumOutlines(const cv::Mat& lab, const cv::Mat& particles, double blur,
                            double maxBackgroundSpread);

}  // namespace solidtex::segmentation::detail
