#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace solidtex::test {

struct Disc {
  cv::Point2f centre;
  float radius;
  cv::Vec3f srgb;
};

// A fresh, empty folder for the running test.
std::filesystem::path freshTempDir();

// CV_32FC3 sRGB photo: flat background, filled discs, then Gaussian noise (fixed seed).
cv::Mat discPhoto(cv::Size size, const cv::Vec3f& background, const std::vector<Disc>& discs,
                  double noise = 0.0);

// CV_8U mask of the discs (255 inside).
cv::Mat discMask(cv::Size size, const std::vector<Disc>& discs);

void writeBytes(const std::filesystem::path& path, const std::vector<unsigned char>& bytes);
std::vector<unsigned char> readBytes(const std::filesystem::path& path);

// A PNG whose header claims width x height, followed by a token IDAT: no real pixels.
std::vector<unsigned char> pngHeaderClaiming(unsigned width, unsigned height);

std::string dataPath(const std::string& relative);

}  // namespace solidtex::test
