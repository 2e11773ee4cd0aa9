#include "pipeline/comparisonPlot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace solidtex {
namespace {

const cv::Scalar kPhotoColor(0.12, 0.47, 0.71), kVolumeColor(1.0, 0.50, 0.05), kInk(0.15, 0.15, 0.15);
const cv::Scalar kTruthColor(0.17, 0.63, 0.17);
constexpr int kPanelWidth = 520, kPanelHeight = 380, kMargin = 50;

void text(cv::Mat& canvas, const std::string& s, cv::Point at, double size = 0.5, cv::Scalar color = kInk) {
  cv::putText(canvas, s, at, cv::FONT_HERSHEY_SIMPLEX, size, color, 1, cv::LINE_AA);
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
    cv::rectangle(panel, cv::Rect(x, y0 - h1, bar, h1), kPhotoColor, cv::FILLED);
    cv::rectangle(panel, cv::Rect(x + bar + 2, y0 - h2, bar, h2), kVolumeColor, cv::FILLED);
    text(panel, std::to_string(b + 1), {x + bar - 4, y0 + 16}, 0.4);
  }
  char label[32];
  std::snprintf(label, sizeof label, "%.2f", top);
  text(panel, label, {6, 54}, 0.4);
  text(panel, "photo areas", {kPanelWidth - 160, 50}, 0.45, kPhotoColor);
  text(panel, data.volumeLabel, {kPanelWidth - 160 - std::max(0, 8 * int(data.volumeLabel.size()) - 150), 70},
       0.45, kVolumeColor);
  return panel;
}

void drawCdf(cv::Mat& panel, std::vector<double> values, double minX, double maxX, const cv::Scalar& color) {
  if (values.empty() || !(maxX > minX)) return;
  std::sort(values.begin(), values.end());
  const int x0 = kMargin, y0 = kPanelHeight - kMargin, w = kPanelWidth - x0 - 20, h = y0 - 50;
  cv::Point previous(x0, y0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    const int x = x0 + int(w * (std::clamp(values[i], minX, maxX) - minX) / (maxX - minX));
    const int y = y0 - int(h * double(i + 1) / double(values.size()));
    cv::line(panel, previous, {x, previous.y}, color, 2, cv::LINE_AA);
    cv::line(panel, {x, previous.y}, {x, y}, color, 2, cv::LINE_AA);
    previous = {x, y};
  }
}

// The CDFs of one measure of the photo and of the sections, with lines of figures where the CDFs leave room.
cv::Mat cdfPanel(const std::string& title, const std::string& xLabel, const std::vector<double>& photo,
                 const std::vector<double>& sections, double minX, double maxX,
                 const std::vector<std::string>& lines, int linesX) {
  cv::Mat panel(kPanelHeight, kPanelWidth, CV_32FC3, cv::Scalar(1, 1, 1));
  axes(panel, title, xLabel);
  drawCdf(panel, photo, minX, maxX, kPhotoColor);
  drawCdf(panel, sections, minX, maxX, kVolumeColor);
  char label[32];
  std::snprintf(label, sizeof label, "%.3g", minX);
  text(panel, label, {kMargin - 10, kPanelHeight - kMargin + 16}, 0.4);
  std::snprintf(label, sizeof label, "%.3g", maxX);
  text(panel, label, {kPanelWidth - 60, kPanelHeight - kMargin + 16}, 0.4);
  for (std::size_t i = 0; i < lines.size(); ++i)
    text(panel, lines[i], {linesX, kPanelHeight - kMargin - 20 - 20 * int(lines.size() - 1 - i)}, 0.45);
  text(panel, "photo", {kPanelWidth - 160, 50}, 0.45, kPhotoColor);
  text(panel, "sections of the solid", {kPanelWidth - 160, 70}, 0.45, kVolumeColor);
  return panel;
}

std::string format(const char* pattern, double a, double b = 0) {
  char line[96];
  std::snprintf(line, sizeof line, pattern, a, b);
  return line;
}

cv::Mat areaPanel(const ComparisonData& data, const nlohmann::json& report) {
  double maxX = 1;
  for (const auto* values : {&data.photoAreas, &data.sectionAreas})
    if (!values->empty()) maxX = std::max(maxX, *std::max_element(values->begin(), values->end()));
  return cdfPanel(
      "CDF of section areas vs photo particle areas", "area (voxels^2)", data.photoAreas, data.sectionAreas,
      0, maxX,
      {format("KS %.3f   W1/mean %.3f", report.value("ks", 0.0), report.value("wasserstein1_over_mean", 0.0)),
       format("area fraction: photo %.3f", report.value("area_fraction", 0.0)),
       format("volume %.3f  sections %.3f", report.value("volume_fraction", 0.0),
              report.value("section_area_fraction", 0.0))},
      kMargin + 170);
}

cv::Mat shapePanel(const ComparisonData& data, const nlohmann::json& report) {
  const nlohmann::json& c = report.at("shape_and_arrangement");
  return cdfPanel(
      "CDF of solidity (area / convex hull area)", "solidity", data.photoSolidity, data.sectionSolidity, 0.5,
      1,
      {format("solidity KS %.3f  roundness KS %.3f", c.value("solidity_ks", 0.0),
              c.value("roundness_ks", 0.0)),
       format("window spread: photo %.3f  sections %.3f", c["photo"].value("window_spread", 0.0),
              c["sections"].value("window_spread", 0.0)),
       format("nearest neighbour / diameter: %.2f vs %.2f", c["photo"].value("neighbour_distance_mean", 0.0),
              c["sections"].value("neighbour_distance_mean", 0.0))},
      kMargin + 10);
}

// The 3D volume CDF's band (grey) with the solid's placed particles (orange) and the truth's
// (green) over log volume: where the truth's curve leaves the band, the sizing missed it.
cv::Mat volumeBandPanel(const ComparisonData& data) {
  cv::Mat panel(kPanelHeight, kPanelWidth, CV_32FC3, cv::Scalar(1, 1, 1));
  axes(panel, "3D particle volumes: CDF, sizing's 5-95 % band", "volume (photo pixels^3, log)");
  const VolumeCdfBand& band = data.volumeBand;
  std::size_t first = 0, last = band.volumes.size() - 1;
  while (first + 1 < last && band.high[first + 1] <= 1e-3) ++first;
  while (last > first + 1 && band.low[last - 1] >= 1 - 1e-3) --last;
  const double lo = std::log(band.volumes[first]), hi = std::log(band.volumes[last]);
  const int x0 = kMargin, y0 = kPanelHeight - kMargin, w = kPanelWidth - x0 - 20, h = y0 - 50;
  const auto xOf = [&](double v) {
    return x0 + int(w * std::clamp((std::log(v) - lo) / (hi - lo), 0.0, 1.0));
  };
  const auto yOf = [&](double f) { return y0 - int(h * f); };
  std::vector<cv::Point> area;
  for (std::size_t i = first; i <= last; ++i) area.emplace_back(xOf(band.volumes[i]), yOf(band.high[i]));
  for (std::size_t i = last + 1; i-- > first;) area.emplace_back(xOf(band.volumes[i]), yOf(band.low[i]));
  cv::fillPoly(panel, std::vector<std::vector<cv::Point>>{area}, cv::Scalar(0.82, 0.82, 0.82), cv::LINE_AA);
  const auto curve = [&](std::vector<double> values, const cv::Scalar& color) {
    std::sort(values.begin(), values.end());
    cv::Point previous(x0, y0);
    for (std::size_t i = 0; i < values.size(); ++i) {
      const cv::Point next(xOf(values[i]), yOf(double(i + 1) / double(values.size())));
      cv::line(panel, previous, {next.x, previous.y}, color, 2, cv::LINE_AA);
      cv::line(panel, {next.x, previous.y}, next, color, 2, cv::LINE_AA);
      previous = next;
    }
  };
  curve(data.solidVolumes, kVolumeColor);
  text(panel, "placed particles", {kPanelWidth - 170, kPanelHeight - kMargin - 40}, 0.45, kVolumeColor);
  if (!data.truthVolumes.empty()) {
    curve(data.truthVolumes, kTruthColor);
    text(panel, "truth", {kPanelWidth - 170, kPanelHeight - kMargin - 20}, 0.45, kTruthColor);
  }
  text(panel, "band", {kPanelWidth - 170, kPanelHeight - kMargin - 60}, 0.45, cv::Scalar(0.5, 0.5, 0.5));
  text(panel, format("%.3g", band.volumes[first]), {kMargin - 10, kPanelHeight - kMargin + 16}, 0.4);
  text(panel, format("%.3g", band.volumes[last]), {kPanelWidth - 60, kPanelHeight - kMargin + 16}, 0.4);
  return panel;
}

}  // namespace

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
  std::vector<cv::Mat> panels{histogramPanel(data), areaPanel(data, report), shapePanel(data, report)};
  if (!data.volumeBand.volumes.empty()) panels.push_back(volumeBandPanel(data));
  cv::hconcat(panels, canvas);
  return canvas;
}

}  // namespace solidtex
