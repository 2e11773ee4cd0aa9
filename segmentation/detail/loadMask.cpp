#include "segmentation/detail/loadMask.h"

#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "segmentation/imageIO.h"

namespace solidtex::detail {

cv::Mat loadMask(const std::string& path, const cv::Size& photoSize) {
  const cv::Mat rgb = loadPhoto(path);
  if (rgb.size() != photoSize)
    throw InputError(path + ": mask is " + std::to_string(rgb.cols) + "x" + std::to_string(rgb.rows) +
                     " but the photo is " + std::to_string(photoSize.width) + "x" +
                     std::to_string(photoSize.height));
  cv::Mat grey;
  cv::cvtColor(rgb, grey, cv::COLOR_RGB2GRAY);
  return grey > 0.5f;
}

}  // namespace solidtex::detail
