#include "segmentation/imageIO.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <unistd.h>

#include <OpenImageIO/imageio.h>

#include "common/Error.h"
#include "segmentation/detail/color.h"

namespace solidtex {
namespace {

// OpenImageIO messages can span lines; the command line promises one line per error.
std::string oneLine(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  while (!message.empty() && message.back() == ' ') message.pop_back();
  return message.empty() ? "unknown error" : message;
}

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw InputError(path + ": " + problem);
}

std::unique_ptr<OIIO::ImageInput> openImage(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "file not found");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not an image");
  // Colour, not colour times coverage: keep RGBA files' colour as stored.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in) fail(path, "not an image OpenImageIO can read (" + oneLine(OIIO::geterror()) + ")");
  return in;
}

void checkSize(const std::string& path, const OIIO::ImageSpec& spec) {
  const std::string size = std::to_string(spec.width) + "x" + std::to_string(spec.height);
  if (spec.width > kMaxPhotoSide || spec.height > kMaxPhotoSide)
    fail(path, "image is " + size + ", larger than the " + std::to_string(kMaxPhotoSide) + "x" +
                   std::to_string(kMaxPhotoSide) + " limit");
  if (spec.width < kMinPhotoSide || spec.height < kMinPhotoSide)
    fail(path, "image is " + size + ", too small (each side must be at least " +
                   std::to_string(kMinPhotoSide) + " pixels)");
  if (spec.depth > 1) fail(path, "is a volume image, not a photo");
  if (spec.nchannels < 1) fail(path, "image has no channels");
}

bool isLinearEncoded(const OIIO::ImageSpec& spec) {
  std::string space = spec.get_string_attribute("oiio:ColorSpace");
  std::transform(space.begin(), space.end(), space.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return space == "linear" || space == "scene_linear" || space == "lin_srgb" || space == "lin_rec709";
}

// Grey is repeated into R,G,B; channels beyond the third (alpha, extra) are ignored.
cv::Mat toRgb(const std::vector<float>& pixels, int width, int height, int channels) {
  cv::Mat rgb(height, width, CV_32FC3);
  for (int y = 0; y < height; ++y) {
    const float* in = pixels.data() + std::size_t(y) * width * channels;
    auto* out = rgb.ptr<cv::Vec3f>(y);
    for (int x = 0; x < width; ++x, in += channels) {
      const bool grey = channels < 3;
      out[x] = {in[0], grey ? in[0] : in[1], grey ? in[0] : in[2]};
    }
  }
  return rgb;
}

cv::Mat toRgb8(const std::string& path, const cv::Mat& image) {
  if (image.empty()) fail(path, "cannot write an empty image");
  if (image.type() == CV_8UC3 || image.type() == CV_8UC1) return image;
  if (image.type() == CV_32FC3 || image.type() == CV_32FC1) {
    cv::Mat bytes;
    image.convertTo(bytes, image.type() == CV_32FC3 ? CV_8UC3 : CV_8UC1, 255.0);  // saturates and rounds
    return bytes;
  }
  fail(path, "writeImage needs CV_32FC3, CV_8UC3, CV_32FC1 or CV_8UC1 pixels");
}

std::string temporaryName(const std::string& path) { return path + ".tmp" + std::to_string(::getpid()); }

}  // namespace

cv::Mat loadPhoto(const std::string& path) {
  auto in = openImage(path);
  const OIIO::ImageSpec spec = in->spec();
  checkSize(path, spec);
  std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
  const bool ok = in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
  if (!ok)
    fail(path, "cannot decode the image, it may be truncated or corrupt (" + oneLine(in->geterror()) + ")");
  in->close();
  cv::Mat rgb = toRgb(pixels, spec.width, spec.height, spec.nchannels);
  cv::patchNaNs(rgb, 0.0);
  if (isLinearEncoded(spec)) return detail::linearToSrgb(rgb);
  cv::min(cv::max(rgb, 0.0), 1.0, rgb);
  return rgb;
}

void writeImage(const std::string& path, const cv::Mat& srgb) {
  const cv::Mat bytes = toRgb8(path, srgb);
  const cv::Mat packed = bytes.isContinuous() ? bytes : bytes.clone();
  const std::string tmp = temporaryName(path);
  auto out = OIIO::ImageOutput::create("png");
  if (!out) fail(path, "no PNG writer available (" + oneLine(OIIO::geterror()) + ")");
  const OIIO::ImageSpec spec(packed.cols, packed.rows, packed.channels(), OIIO::TypeDesc::UINT8);
  bool ok = out->open(tmp, spec) && out->write_image(OIIO::TypeDesc::UINT8, packed.data);
  ok = out->close() && ok;
  if (!ok) {
    const std::string why = oneLine(out->geterror());
    std::error_code ec;
    std::filesystem::remove(tmp, ec);
    fail(path, "cannot write image (" + why + ")");
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    fail(path, "cannot write image (rename failed: " + ec.message() + ")");
  }
}

}  // namespace solidtex
