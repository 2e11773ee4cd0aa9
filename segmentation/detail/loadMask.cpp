#include "segmentation/detail/loadMask.h"

#include "common/Error.h"
#include "io/imageIO.h"
#include "segmentation/analyzeExemplar.h"

namespace solidtex::segmentation::detail {

cv::Mat loadMask(const std::string& path, const cv::Size& photoSize) {
  const cv::Mat rgb = loadPhoto(path);
  if (rgb.size() != photoSize)
    throw InputError(path + ": mask is " + std::to_string(rgb.cols) + "x" + std::to_string(rgb.rows) +
                     " but the photo is " + std::to_string(photoSize.width) + "x" +
                     std::to_string(photoSize.height));
  return maskFromImage(rgb);
}

}  // namespace solidtex::segmentation::detail
