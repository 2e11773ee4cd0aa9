#include "pipeline/comparisonPlot.h"

#include <algorithm>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace solidtex {
namespace {

const cv::Scalar kPhotoColour(0.12, 0.47, 0.71), kVolumeColour(1.0, 0.50, 0.05), kInk(0.15, 0.15, 0.15);
constexpr int kPanelWidth = 520, kPanelHeight = 380, kMargin = 50;

void text(cv::Mat& canvas, const std::string& s, cv::Point at, double size = 0.5, cv::Scalar colour = kInk) {
  cv::putText(canvas, s, at, cv::FONT_HERSHEY_SIMPLEX, size, colour, 1, cv::LINE_AA);
}

void axes(cv::Mat& panel, const std::string& title, const std::string& xLabel) {
  const int x0 = kMargin, y0 = kPanelHeight - kMargin;
  cv::line(panel, {x0, y0}, {kPanelWidth - 15, y0}, kInk, 1, cv::LINE_AA);
  cv::line(panel, {x0, y0}, {x0, 40}, kInk, 1, cv::LINE_AA);
  text(panel, title, {x0, 25}, 0.55);
  text(panel, xLabel, {kPanelWidth / 2 - 60, kPanelHeight - 12}, 0.45);
}

cv::Mat histogramPanel(const ComparisonData& data) {
  cv::Mat panel(kPanelHeight, kPanelWidth, CV_32FC3, cv::Scalar(1, 1, 1));
  axes(panel, "area histogram (photo) vs volume histogram (solid)", "bin (small to large)");
  const double top = std::max(*std::max_element(data.areaHistogram.begin(), data.areaHistogram.end()),
                              *std::max_element(data.volumeHistogram.begin(), data.volumeHistogram.end()));
  const int x0 = kMargin + 8, y0 = kPanelHeight - kMargin, plotHeight = y0 - 50;
  const int slot = (kPanelWidth - x0 - 20) / 10, bar = slot / 2 - 3;
  for (int b = 0; b < 10; ++b) {
    const int h1 = int(plotHeight * data.areaHistogram[std::size_t(b)] / std::max(top, 1e-9));
    const int h2 = int(plotHeight * data.volumeHistogram[std::size_t(b)] / std::max(top, 1e-9));
    const int x = x0 + b * slot;
    cv::rectangle(panel, cv::Rect(x, y0 - h1, bar, h1), kPhotoColour, cv::FILLED);
    cv::rectangle(panel, cv::Rect(x + bar + 2, y0 - h2, bar, h2), kVolumeColour, cv::FILLED);
    text(panel, std::to_string(b + 1), {x + bar - 4, y0 + 16}, 0.4);
  }
  char label[32];
  std::snprintf(label, sizeof label, "%.2f", top);
  text(panel, label, {6, 54}, 0.4);
  text(panel, "photo areas", {kPanelWidth - 160, 50}, 0.45, kPhotoColour);
  text(panel, "solid volumes", {kPanelWidth - 160, 70}, 0.45, kVolumeColour);
  return panel;
}

void drawCdf(cv::Mat& panel, std::vector<double> values, double maxX, const cv::Scalar& colour) {
  if (values.empty()) return;
  std::sort(values.begin(), values.end());
  const int x0 = kMargin, y0 = kPanelHeight - kMargin, w = kPanelWidth - x0 - 20, h = y0 - 50;
  cv::Point previous(x0, y0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const int x = x0 + int(w * std::min(values[i], maxX) / maxX);
    const int y = y0 - int(h * double(i + 1) / double(values.size()));
    cv::line(panel, previous, {x, previous.y}, colour, 2, cv::LINE_AA);
    cv::line(panel, {x, previous.y}, {x, y}, colour, 2, cv::LINE_AA);
    previous = {x, y};
  }
}

cv::Mat cdfPanel(const ComparisonData& data, const nlohmann::json& report) {
  cv::Mat panel(kPanelHeight, kPanelWidth, CV_32FC3, cv::Scalar(1, 1, 1));
  axes(panel, "CDF of section areas vs photo particle areas", "area (voxels^2)");
  double maxX = 1;
  for (const auto* values : {&data.photoAreas, &data.sectionAreas})
    if (!values->empty()) maxX = std::max(maxX, *std::max_element(values->begin(), values->end()));
  drawCdf(panel, data.photoAreas, maxX, kPhotoColour);
  drawCdf(panel, data.sectionAreas, maxX, kVolumeColour);
  char line[96];
  std::snprintf(line, sizeof line, "max %.0f", maxX);
  text(panel, line, {kPanelWidth - 90, kPanelHeight - kMargin + 16}, 0.4);
  const int x = kMargin + 190;
  std::snprintf(line, sizeof line, "KS %.3f   W1/mean %.3f", report.value("ks", 0.0), report.value("wasserstein1_over_mean", 0.0));
  text(panel, line, {x, kPanelHeight - kMargin - 60}, 0.5);
  std::snprintf(line, sizeof line, "area fraction: photo %.3f", report.value("area_fraction", 0.0));
  text(panel, line, {x, kPanelHeight - kMargin - 40}, 0.45);
  std::snprintf(line, sizeof line, "volume %.3f  sections %.3f", report.value("volume_fraction", 0.0),
                report.value("section_area_fraction", 0.0));
  text(panel, line, {x, kPanelHeight - kMargin - 22}, 0.45);
  text(panel, "photo", {kPanelWidth - 160, 50}, 0.45, kPhotoColour);
  text(panel, "sections of the solid", {kPanelWidth - 160, 70}, 0.45, kVolumeColour);
  return panel;
}

} // namespace

std::array<double, 10> tenBinRatios(const std::vector<double>& values) {
  std::array<double, 10> ratios{};
  if (values.empty()) return ratios;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  const double width = (*hi - *lo) / 10;
  for (double v : values) ratios[std::size_t(width > 0 ? std::min(9, int((v - *lo) / width)) : 0)] += 1;
  for (double& r : ratios) r /= double(values.size());
  return ratios;
}

cv::Mat plotComparison(const ComparisonData& data, const nlohmann::json& report) {
  cv::Mat canvas;
  cv::hconcat(histogramPanel(data), cdfPanel(data, report), canvas);
  return canvas;
}

} // namespace solidtex
