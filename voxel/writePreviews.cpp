#include "voxel/writePreviews.h"

#include <algorithm>
#include <filesystem>

#include <opencv2/imgproc.hpp>

#include "common/Error.h"
#include "io/imageIO.h"
#include "voxel/slice.h"

namespace solidtex {
namespace {

constexpr int kPreviewHeight = 320;

/// Nearest-neighbour scaling to a common height keeps voxels crisp, as a person expects to see them.
cv::Mat toHeight(const cv::Mat& image, int height) {
  cv::Mat out;
  const int width = std::max(1, int(std::lround(double(image.cols) * height / image.rows)));
  cv::resize(image, out, cv::Size(width, height), 0, 0,
             image.rows < height ? cv::INTER_NEAREST : cv::INTER_AREA);
  return out;
}

cv::Mat sideBySide(const std::vector<cv::Mat>& images) {
  constexpr int gap = 8;
  int width = gap;
  for (const auto& im : images) width += im.cols + gap;
  cv::Mat canvas(kPreviewHeight + 2 * gap, width, CV_32FC3, cv::Scalar(1, 1, 1));
  int x = gap;
  for (const auto& im : images) {
    im.copyTo(canvas(cv::Rect(x, gap, im.cols, im.rows)));
    x += im.cols + gap;
  }
  return canvas;
}

}  // namespace

std::vector<std::string> writePreviews(OutputFiles& outputs, const std::string& dir, const cv::Mat& photoSrgb,
                                       const SolidVolume& volume) {
  namespace fs = std::filesystem;
  const Dims& d = volume.dims;
  const Eigen::Vector3d centre((d.x - 1) * 0.5, (d.y - 1) * 0.5, (d.z - 1) * 0.5);
  const std::pair<const char*, SlicePlane> planes[] = {
      {"slice_x.png", axisPlane(d, 0, d.x / 2)},
      {"slice_y.png", axisPlane(d, 1, d.y / 2)},
      {"slice_z.png", axisPlane(d, 2, d.z / 2)},
      {"slice_oblique.png", obliquePlane(d, Eigen::Vector3d(1, 2, 3), centre)},
  };
  std::vector<std::string> written;
  std::vector<cv::Mat> row{toHeight(photoSrgb, kPreviewHeight)};
  for (const auto& [name, plane] : planes) {
    const cv::Mat image = toHeight(colorSlice(volume, plane), kPreviewHeight);
    const std::string path = (fs::path(dir) / name).string();
    outputs.write(path, [&](const std::string& file) { writeImage(file, image); });
    written.push_back(path);
    row.push_back(image);
  }
  const std::string montage = (fs::path(dir) / "preview.png").string();
  const cv::Mat montageImage = sideBySide(row);
  outputs.write(montage, [&](const std::string& file) { writeImage(file, montageImage); });
  written.push_back(montage);
  return written;
}

}  // namespace solidtex
