#include "io/imageIO.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "common/Error.h"
#include "common/memoryBudget.h"
#include "common/srgb.h"
#include "common/writeFileBytes.h"
#include "io/detail/CapturedStderr.h"
#include "io/detail/checkImageLayout.h"

namespace solidtex {
namespace {

// Decoded floats held at a time: small enough to stay in cache, which reads faster than whole.
constexpr double kStripBytes = 1 << 20;
// Peak bytes per pixel of loadPhoto + analyzeExemplar: 92-98 measured (peak RSS of gravel.png
// scaled to 4 and 33 Mpx, coins tiled to 15 Mpx), plus a margin for photos with more undecided
// edge pixels in the watershed queue.
constexpr double kPhotoBytesPerPixel = 110;

// OpenImageIO messages can span lines; the command line promises one line per error.
std::string oneLine(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  while (!message.empty() && message.back() == ' ') message.pop_back();
  return message.empty() ? "unknown error" : message;
}

// OpenImageIO's message, plus what the codec library printed itself (libpng's "bad adaptive
// filter value" says more than "read error") unless it only repeats it, "libpng error: " aside.
std::string withPrinted(const std::string& message, const std::string& printed) {
  const std::string mine = oneLine(message);
  const std::size_t colon = printed.find(": ");
  const std::string gist = colon == std::string::npos ? printed : printed.substr(colon + 2);
  if (printed.empty() || mine.find(gist) != std::string::npos) return mine;
  return mine == "unknown error" ? printed : mine + "; " + printed;
}

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw InputError(path + ": " + problem);
}

std::unique_ptr<OIIO::ImageInput> openImage(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "file not found");
  if (std::filesystem::is_directory(path, ec)) fail(path, "is a directory, not an image");
  if (const std::string problem = io::detail::imageLayoutProblem(path); !problem.empty())
    fail(path, "cannot decode the image, it is truncated or corrupt (" + problem + ")");
  // Colour, not colour times coverage: keep RGBA files' colour as stored.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  io::detail::CapturedStderr libraryOutput;
  auto in = OIIO::ImageInput::open(path, &config);
  const std::string printed = libraryOutput.finish();
  if (!in) fail(path, "not an image OpenImageIO can read (" + withPrinted(OIIO::geterror(), printed) + ")");
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
void copyRows(const std::vector<float>& strip, int channels, int firstRow, cv::Mat& rgb) {
  const int rows = int(strip.size() / (std::size_t(rgb.cols) * channels));
  for (int r = 0; r < rows && firstRow + r < rgb.rows; ++r) {
    const float* in = strip.data() + std::size_t(r) * rgb.cols * channels;
    auto* out = rgb.ptr<cv::Vec3f>(firstRow + r);
    for (int x = 0; x < rgb.cols; ++x, in += channels) {
      const bool grey = channels < 3;
      out[x] = {in[0], grey ? in[0] : in[1], grey ? in[0] : in[2]};
    }
  }
}

// Rows a strip holds: whole tiles for tiled files, about kStripBytes of floats otherwise.
int stripRows(const OIIO::ImageSpec& spec) {
  const double rowBytes = double(spec.width) * spec.nchannels * sizeof(float);
  const int rows = std::max(1, int(kStripBytes / rowBytes));
  if (spec.tile_height <= 0) return rows;
  return std::max(1, rows / spec.tile_height) * spec.tile_height;
}

// Rows [y0, y1) of the image (0 = its first row) as floats, all channels.
bool readRows(OIIO::ImageInput& in, const OIIO::ImageSpec& spec, int y0, int y1, std::vector<float>& strip) {
  strip.resize(std::size_t(y1 - y0) * spec.width * spec.nchannels);
  if (spec.tile_width > 0)
    return in.read_tiles(0, 0, spec.x, spec.x + spec.width, spec.y + y0, spec.y + y1, spec.z,
                         spec.z + std::max(1, spec.depth), 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                         strip.data());
  return in.read_scanlines(0, 0, spec.y + y0, spec.y + y1, spec.z, 0, spec.nchannels, OIIO::TypeDesc::FLOAT,
                           strip.data());
}

// Decodes a strip at a time straight into the result: no whole-image float buffer, and a file
// whose header promises more than it holds fails having touched only the rows it really has (the
// result's untouched pages cost no memory).
cv::Mat decodeRgb(const std::string& path, OIIO::ImageInput& in, const OIIO::ImageSpec& spec) {
  cv::Mat rgb(spec.height, spec.width, CV_32FC3);
  std::vector<float> strip;
  const int step = stripRows(spec);
  io::detail::CapturedStderr libraryOutput;
  for (int y = 0; y < spec.height; y += step) {
    if (!readRows(in, spec, y, std::min(spec.height, y + step), strip)) {
      const std::string message = in.geterror();
      fail(path, "cannot decode the image, it may be truncated or corrupt (" +
                     withPrinted(message, libraryOutput.finish()) + ")");
    }
    copyRows(strip, spec.nchannels, y, rgb);
  }
  in.close();
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

}  // namespace

cv::Mat loadPhoto(const std::string& path) {
  auto in = openImage(path);
  const OIIO::ImageSpec spec = in->spec();
  checkSize(path, spec);
  requireMemory("decoding and analysing the " + std::to_string(spec.width) + "x" +
                    std::to_string(spec.height) + " photo " + std::filesystem::path(path).filename().string(),
                photoMemoryBytes(spec.width, spec.height));
  cv::Mat rgb = decodeRgb(path, *in, spec);
  cv::patchNaNs(rgb, 0.0);
  if (isLinearEncoded(spec))
    rgb.forEach<cv::Vec3f>([](cv::Vec3f& pixel, const int*) {
      for (int c = 0; c < 3; ++c) pixel[c] = linearToSrgb(pixel[c]);
    });
  cv::min(cv::max(rgb, 0.0), 1.0, rgb);
  return rgb;
}

std::optional<std::array<double, 2>> pixelSizeOf(const std::string& path) {
  const OIIO::ImageSpec spec = openImage(path)->spec();
  const std::string unit = spec.get_string_attribute("ResolutionUnit");
  const double metres = unit == "in" || unit == "inch" ? 0.0254
                        : unit == "cm"                 ? 0.01
                        : unit == "mm"                 ? 0.001
                        : unit == "m"                  ? 1.0
                                                       : 0.0;
  const double x = spec.get_float_attribute("XResolution"), y = spec.get_float_attribute("YResolution");
  if (!(metres > 0) || !(x > 0) || !(y > 0) || !std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
  return std::array<double, 2>{metres / x, metres / y};
}

cv::Mat photoFromPixels(const void* pixels, PixelType type, int width, int height, int channels,
                        const std::string& name) {
  if (channels != 1 && channels != 3 && channels != 4)
    fail(name, "a photo has 1 (grey), 3 (RGB) or 4 (RGBA) channels, not " + std::to_string(channels));
  OIIO::ImageSpec spec(width, height, channels);
  checkSize(name, spec);
  cv::Mat rgb(height, width, CV_32FC3);
  std::vector<float> strip;
  const std::size_t rowValues = std::size_t(width) * std::size_t(channels);
  const int step = std::max(1, int(kStripBytes / (double(rowValues) * sizeof(float))));
  const OIIO::TypeDesc from = type == PixelType::UInt8 ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT;
  for (int y = 0; y < height; y += step) {
    const int rows = std::min(height - y, step);
    strip.resize(std::size_t(rows) * rowValues);
    const auto* first = static_cast<const unsigned char*>(pixels) + std::size_t(y) * rowValues * from.size();
    OIIO::convert_pixel_values(from, first, OIIO::TypeDesc::FLOAT, strip.data(), int(strip.size()));
    copyRows(strip, channels, y, rgb);
  }
  cv::patchNaNs(rgb, 0.0);
  cv::min(cv::max(rgb, 0.0), 1.0, rgb);
  return rgb;
}

double photoMemoryBytes(int width, int height) {
  return kPhotoBytesPerPixel * double(width) * double(height) + kStripBytes;
}

void writeImage(const std::string& path, const cv::Mat& srgb) {
  const cv::Mat bytes = toRgb8(path, srgb);
  const cv::Mat packed = bytes.isContinuous() ? bytes : bytes.clone();
  auto out = OIIO::ImageOutput::create("png");
  if (!out) fail(path, "no PNG writer available (" + oneLine(OIIO::geterror()) + ")");
  // Encoded in memory, then written with every write checked: OpenImageIO's own file writing
  // does not report a full disk.
  std::vector<unsigned char> encoded;
  OIIO::Filesystem::IOVecOutput memory(encoded);
  const OIIO::ImageSpec spec(packed.cols, packed.rows, packed.channels(), OIIO::TypeDesc::UINT8);
  io::detail::CapturedStderr libraryOutput;
  bool ok = out->set_ioproxy(&memory) && out->open(path, spec) &&
            out->write_image(OIIO::TypeDesc::UINT8, packed.data);
  ok = out->close() && ok;
  const std::string printed = libraryOutput.finish();
  if (!ok) fail(path, "cannot encode the image (" + withPrinted(out->geterror(), printed) + ")");
  writeFileBytes(path, encoded.data(), encoded.size());
}

}  // namespace solidtex
