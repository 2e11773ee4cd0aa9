#include "pipeline/materialsPlot.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace solidtex {
namespace {

const cv::Scalar kInk(0.15, 0.15, 0.15);
// Photo, sections, solid: the comparison plot's blue and orange, and green for the 3D solid.
const cv::Scalar kColors[3] = {{0.12, 0.47, 0.71}, {1.0, 0.50, 0.05}, {0.17, 0.63, 0.17}};
const char* kFields[3] = {"photo", "sections", "solid"};
constexpr int kHeight = 340, kMargin = 44;

void text(cv::Mat& panel, const std::string& s, cv::Point at, double size, const cv::Scalar& color = kInk) {
  cv::putText(panel, s, at, cv::FONT_HERSHEY_SIMPLEX, size, color, 1, cv::LINE_AA);
}

std::string number(double v) {
  char s[32];
  std::snprintf(s, sizeof s, "%.3g", v);
  return s;
}

struct Curve {
  std::vector<double> x, y;
};

// Curves of the photo, the sections and the solid on shared axes from 0, with a line of figures.
// Points beyond xLimit (when > 0) are left out: the curves' tails are flat.
cv::Mat curvePanel(int width, const std::string& title, const std::string& xLabel, const Curve (&curves)[3],
                   const std::string& figures, double xLimit = 0) {
  cv::Mat panel(kHeight, width, CV_32FC3, cv::Scalar(1, 1, 1));
  const int x0 = kMargin, y0 = kHeight - kMargin, w = width - x0 - 16, h = y0 - 56;
  double maxX = 1e-9, maxY = 1e-9;
  for (const Curve& c : curves)
    for (std::size_t i = 0; i < c.x.size(); ++i)
      if (xLimit <= 0 || c.x[i] <= xLimit) maxX = std::max(maxX, c.x[i]), maxY = std::max(maxY, c.y[i]);
  cv::line(panel, {x0, y0}, {width - 10, y0}, kInk, 1, cv::LINE_AA);
  cv::line(panel, {x0, y0}, {x0, 50}, kInk, 1, cv::LINE_AA);
  text(panel, title, {x0, 22}, 0.5);
  text(panel, xLabel, {width / 2 - 40, kHeight - 10}, 0.42);
  text(panel, number(maxX), {width - 50, y0 + 16}, 0.38);
  text(panel, number(maxY), {4, 58}, 0.38);
  text(panel, figures, {x0 + 8, 42}, 0.42);
  for (int f = 0; f < 3; ++f) {
    const Curve& c = curves[f];
    for (std::size_t i = 1; i < c.x.size() && c.x[i] <= maxX; ++i)
      cv::line(panel, {x0 + int(w * c.x[i - 1] / maxX), y0 - int(h * c.y[i - 1] / maxY)},
               {x0 + int(w * c.x[i] / maxX), y0 - int(h * c.y[i] / maxY)}, kColors[f], 2, cv::LINE_AA);
    text(panel, kFields[f], {width - 90, 64 + 18 * f}, 0.42, kColors[f]);
  }
  return panel;
}

// values[i] at x = first + i * step.
Curve againstIndex(const nlohmann::json& values, double step = 1, double first = 0) {
  Curve c;
  if (!values.is_array()) return c;
  for (std::size_t i = 0; i < values.size(); ++i)
    c.x.push_back(first + double(i) * step), c.y.push_back(values[i]);
  return c;
}

}  // namespace

cv::Mat plotMaterials(const nlohmann::json& materials, int width) {
  const nlohmann::json& phases = materials.at("phases");
  if (phases.empty()) return {};
  const std::string name = phases.contains("particles") ? "particles" : phases.begin().key();
  const nlohmann::json& p = phases.at(name);
  const int panelWidth = width / 4;
  const nlohmann::json& s = p.at("sections_vs_photo");
  std::vector<cv::Mat> panels;
  Curve curves[3];
  // Show separations to eight correlation lengths and chords to four mean chords of the photo's.
  const double reach =
      8 * std::max(1.0, p["photo"].contains("s2") ? p["photo"]["s2"].value("correlation_length", 0.0) : 0.0);
  if (p["photo"].contains("s2")) {
    for (int f = 0; f < 3; ++f) curves[f] = againstIndex(p[kFields[f]]["s2"]["radial"]);
    panels.push_back(curvePanel(panelWidth, "S2(r), " + name, "r (voxels)", curves,
                                "rms sections " + number(s.value("s2_rms", 0.0)), reach));
  }
  if (p["photo"].contains("lineal_path")) {
    for (int f = 0; f < 3; ++f) curves[f] = againstIndex(p[kFields[f]]["lineal_path"]["axis_mean"]);
    panels.push_back(curvePanel(panelWidth, "lineal path L(r), " + name, "r (voxels)", curves,
                                "rms sections " + number(s.value("lineal_path_rms", 0.0)), reach));
  }
  if (p["photo"].contains("chords")) {
    for (int f = 0; f < 3; ++f)
      curves[f] = againstIndex(p[kFields[f]]["chords"]["histogram"],
                               p[kFields[f]]["chords"]["bin_width"].get<double>(),
                               p[kFields[f]]["chords"]["bin_width"].get<double>());
    panels.push_back(curvePanel(panelWidth, "chord lengths, " + name, "length (voxels)", curves,
                                "mean ratio " + number(s.value("chord_mean_ratio", 0.0)),
                                4 * p["photo"]["chords"].value("mean", 1.0)));
  }
  if (p["photo"].contains("local_thickness")) {
    for (int f = 0; f < 3; ++f) {
      const nlohmann::json& t = p[kFields[f]]["local_thickness"];
      curves[f] = {t["radii"].get<std::vector<double>>(), t["cumulative"].get<std::vector<double>>()};
    }
    panels.push_back(curvePanel(panelWidth, "share at least r thick, " + name, "r (voxels)", curves,
                                "mean ratio " + number(s.value("local_thickness_mean_ratio", 0.0))));
  }
  if (panels.empty()) return {};
  while (panels.size() < 4) panels.emplace_back(kHeight, panelWidth, CV_32FC3, cv::Scalar(1, 1, 1));
  cv::Mat row;
  cv::hconcat(panels, row);
  if (row.cols < width)
    cv::copyMakeBorder(row, row, 0, 0, 0, width - row.cols, cv::BORDER_CONSTANT, cv::Scalar(1, 1, 1));
  return row;
}

}  // namespace solidtex
