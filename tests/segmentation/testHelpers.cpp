#include "testHelpers.h"

#include <fstream>
#include <iterator>

#include <gtest/gtest.h>
#include <opencv2/imgproc.hpp>

#include "tests/pngBytes.h"

namespace solidtex::test {
std::filesystem::path freshTempDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) /
      ("solidtex_seg_" + std::string(info->test_suite_name()) + "_" + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

cv::Mat discPhoto(cv::Size size, const cv::Vec3f& background, const std::vector<Disc>& discs, double noise) {
  cv::Mat photo(size, CV_32FC3, cv::Scalar(background[0], background[1], background[2]));
  for (const Disc& d : discs)
    cv::circle(photo, cv::Point(cvRound(d.centre.x), cvRound(d.centre.y)), cvRound(d.radius),
               cv::Scalar(d.srgb[0], d.srgb[1], d.srgb[2]), cv::FILLED, cv::LINE_8);
  if (noise > 0) {
    cv::Mat n(size, CV_32FC3);
    cv::RNG rng(12345);
    rng.fill(n, cv::RNG::NORMAL, 0.0, noise);
    photo += n;
    cv::min(cv::max(photo, 0.0), 1.0, photo);
  }
  return photo;
}

cv::Mat discMask(cv::Size size, const std::vector<Disc>& discs) {
  cv::Mat mask = cv::Mat::zeros(size, CV_8UC1);
  for (const Disc& d : discs)
    cv::circle(mask, cv::Point(cvRound(d.centre.x), cvRound(d.centre.y)), cvRound(d.radius), cv::Scalar(255),
               cv::FILLED, cv::LINE_8);
  return mask;
}

void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

std::vector<unsigned char> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<unsigned char> pngHeaderClaiming(unsigned width, unsigned height) {
  std::vector<unsigned char> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  std::vector<unsigned char> ihdr;
  putU32(ihdr, width);
  putU32(ihdr, height);
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0});  // 8-bit RGB, deflate, no filter, no interlace
  putChunk(png, "IHDR", ihdr);
  putChunk(png, "IDAT", {0x78, 0x9c, 0x03, 0x00, 0x00, 0x00, 0x00, 0x01});  // an empty zlib stream
  putChunk(png, "IEND", {});
  return png;
}

std::string dataPath(const std::string& relative) { return std::string(SOLIDTEX_DATA_DIR) + "/" + relative; }

}  // namespace solidtex::test
