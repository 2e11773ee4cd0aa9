#include "segmentation/detail/loadMask.h"

#include "common/Error.h"
#include "io/imageIO.h"
#include "segmentation/analyzeExemplar.h"

namespace solidtex::segmentation::detail {

cv::Mat loadMask(const std::string& path, const cv::Size& photoSize) {
  const cv::Mat rgb = loadPhoto(path);
  checkMaskSize(rgb.size(), photoSize, path + ": mask");
  return maskFromImage(rgb);
}

void checkMaskSize(const cv::Size& maskSize, const cv::Size& photoSize, const std::string& name) {
  if (maskSize != photoSize)
    throw InputError(name + " is " + std::to_string(maskSize.width) + "x" + std::to_string(maskSize.height) +
                     " but the photo is " + std::to_string(photoSize.width) + "x" +
                     std::to_string(photoSize.height));
}

}  // namespace solidtex::segmentation::detail
