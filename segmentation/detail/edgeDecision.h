#pragma once
#include <opencv2/core.hpp>

#include "segmentation/detail/otsu.h"

namespace solidtex::segmentation::detail {

// Splits pixels by their colour distance from the background (CV_32F) into background (255 in the
// returned CV_8U mask) and particles. Pixels within the background's own spread of distances are
// background and those beyond Otsu's threshold (`split`) are particles; the ones in between (dim
// particles under uneven light, soft shadows, blurred rims) go to whichever side's flood reaches
// them first through the distance's gradient, so the border settles on the visible edge.
cv::Mat backgroundByEdges(const cv::Mat& distance, const OtsuSplit& split);

// The same with the particle seeds given (CV_8U, non-zero on pixels surely particle) and the
// background's spread measured below `threshold`: for photos whose particles lie on both sides of
// the background's colour, each side with a threshold of its own.
cv::Mat backgroundByEdges(const cv::Mat& distance, const cv::Mat& particleSeeds, float threshold);

}  // namespace solidtex::segmentation::detail
