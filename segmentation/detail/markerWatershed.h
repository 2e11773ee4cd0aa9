#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Marker-controlled watershed (Meyer's flooding): `markers` is CV_8U with 0 on undecided pixels
// and a class number elsewhere; every undecided pixel takes the class of the marker whose flood,
// rising through `relief` (CV_32F, e.g. a gradient magnitude), reaches it first, so class borders
// settle on the relief's crests. Ties go first-come first-served, which keeps it deterministic.
cv::Mat markerWatershed(const cv::Mat& markers, const cv::Mat& relief);

}  // namespace solidtex::segmentation::detail
