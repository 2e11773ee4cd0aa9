#pragma once
#include <opencv2/core.hpp>

namespace solidtex::segmentation::detail {

// Undoes cuts that made particles less convex. Distance-transform peaks also appear inside one
// particle whose mask has dents or holes (dark relief on a coin, the pale centre of a leopard
// rosette); cutting there leaves ragged pieces. Two touching particles of `labels` (CV_32S,
// 0 = background) are merged, best gain first, while the union, holes filled, is at least as
// solid (area / convex hull area) as the pieces on average; truly separate bodies touching at a
// neck form a notched, less solid union and stay apart. Relabels 1..N in raster order.
void mergeWhereMoreConvex(cv::Mat& labels);

}  // namespace solidtex::segmentation::detail
