#include "pipeline/spaciousnessPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace solidtex {
namespace {

const cv::Scalar kBar(0.12, 0.47, 0.71), kInk(0.15, 0.15, 0.15), kZero(0.85, 0.2, 0.2);
constexpr int kWidth = 360, kHeight = 300, kMargin = 40, kBins = 41;

void text(cv::Mat& panel, const std::string& s, cv::Point at, double size = 0.45) {
  cv::putText(panel, s, at, cv::FONT_HERSHEY_SIMPLEX, size, kInk, 1, cv::LINE_AA);
}

// Share of the errors per bin of [-range, range], on a square-root scale so that rare large errors show.
cv::Mat panelFor(const FieldErrors& field, double range) {
  cv::Mat panel(kHeight, kWidth, CV_32FC3, cv::Scalar(1, 1, 1));
  std::vector<double> share(kBins, 0);
  for (const double e : field.errors) {
    const int bin = std::clamp(int(std::floor((e + range) / (2 * range) * kBins)), 0, kBins - 1);
    share[std::size_t(bin)] += 1.0 / double(std::max<std::size_t>(1, field.errors.size()));
  }
  const int x0 = kMargin / 2, y0 = kHeight - kMargin, plotHeight = y0 - 70, slot = (kWidth - kMargin) / kBins;
  for (int b = 0; b < kBins; ++b) {
    const int h = int(plotHeight * std::sqrt(share[std::size_t(b)]));
    cv::rectangle(panel, cv::Rect(x0 + b * slot, y0 - h, slot - 1, h), kBar, cv::FILLED);
  }
  const int zeroX = x0 + kBins / 2 * slot + slot / 2;
  cv::line(panel, {zeroX, y0}, {zeroX, y0 - plotHeight}, kZero, 1, cv::LINE_AA);
  cv::line(panel, {x0, y0}, {x0 + kBins * slot, y0}, kInk, 1, cv::LINE_AA);
  char line[96];
  std::snprintf(line, sizeof line, "-%.1f", range);
  text(panel, line, {x0, y0 + 16}, 0.4);
  std::snprintf(line, sizeof line, "+%.1f", range);
  text(panel, line, {x0 + kBins * slot - 30, y0 + 16}, 0.4);
  text(panel, "field - exact (voxels)", {kWidth / 2 - 80, kHeight - 8}, 0.4);
  double mean = 0, worst = 0;
  for (const double e : field.errors) {
    mean += std::abs(e);
    worst = std::max(worst, std::abs(e));
  }
  mean /= double(std::max<std::size_t>(1, field.errors.size()));
  text(panel, field.name, {x0, 22}, 0.6);
  std::snprintf(line, sizeof line, "mean |err| %.3f  max %.2f", mean, worst);
  text(panel, line, {x0, 44});
  return panel;
}

}  // namespace

cv::Mat plotSpaciousnessErrors(const SpaciousnessErrors& fields) {
  double range = 0.5;
  for (const FieldErrors& f : fields)
    for (const double e : f.errors) range = std::max(range, std::abs(e));
  std::vector<cv::Mat> panels;
  for (const FieldErrors& f : fields) panels.push_back(panelFor(f, range));
  cv::Mat canvas;
  cv::hconcat(panels, canvas);
  return canvas;
}

}  // namespace solidtex
