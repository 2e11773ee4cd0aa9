// Measures the continuous synthesis methods on exemplars: coherence, completeness and patch distance
// on axis and oblique slices (validation/continuousQuality.h), position coverage, colour histogram
// distance, time, peak memory. Usage:
//   synthesis_bench [--size N] [--methods chen-wang,kopf] [--iterations I] [--threads T] [--seed S]
//                   [--report-dir DIR] [--slices DIR] EXEMPLAR.png...
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "common/memoryBudget.h"
#include "common/srgb.h"
#include "pipeline/synthesizeJob.h"
#include "synthesis/synthesizeSolid.h"
#include "validation/continuousQuality.h"

namespace {

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) out.push_back(item);
  return out;
}

/// Writes the middle x, y and z slices side by side as an sRGB PNG.
void writeSlices(const solidtex::SolidVolume& v, const std::string& path) {
  const int n = v.dims.x;
  cv::Mat img(n, 3 * n + 8, CV_8UC3, cv::Scalar(0, 0, 0));
  for (int a = 0; a < 3; ++a)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        int x = i, y = j, z = n / 2;
        if (a == 0) x = n / 2, y = i, z = j;
        if (a == 1) x = i, y = n / 2, z = j;
        const auto& c = v.color[v.dims.index(x, y, z)];
        cv::Vec3b& p = img.at<cv::Vec3b>(j, a * (n + 4) + i);
        for (int k = 0; k < 3; ++k)
          p[2 - k] = cv::saturate_cast<uchar>(255.0f * solidtex::linearToSrgb(c[k]) + 0.5f);
      }
  const int scale = std::max(1, 256 / n);
  cv::resize(img, img, cv::Size(), scale, scale, cv::INTER_NEAREST);
  cv::imwrite(path, img);
}

}  // namespace

int main(int argc, char** argv) {
  solidtex::SynthesisOptions base;
  bool measure = true;
  std::vector<std::string> methods{"chen-wang", "kopf"};
  std::vector<std::string> exemplars;
  std::string reportDir, slicesDir;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() { return std::string(argv[++i]); };
    if (a == "--size")
      base.size = std::stoi(next());
    else if (a == "--methods")
      methods = split(next());
    else if (a == "--iterations")
      base.iterations = std::stoi(next());
    else if (a == "--threads")
      base.threads = std::stoi(next());
    else if (a == "--seed")
      base.seed = std::stoull(next());
    else if (a == "--levels")
      base.levels = std::stoi(next());
    else if (a == "--neighborhoods") {
      base.neighborhoods.clear();
      for (const auto& s : split(next())) base.neighborhoods.push_back(std::stoi(s));
    } else if (a == "--report-dir")
      reportDir = next();
    else if (a == "--slices")
      slicesDir = next();
    else if (a == "--no-measure")
      measure = false;
    else if (a == "--no-color-histogram")
      base.colorHistogramMatching = false;
    else if (a == "--choice") {
      const std::string c = next();
      using C = solidtex::ProposalChoice;
      base.choice = c == "average" ? C::NearestToAverage : c == "vote" ? C::LargestVote : C::ColorMode;
    } else if (a == "--bandwidth")
      base.modeBandwidth = std::stod(next());
    else if (a == "--reference-count")
      base.histogramReferenceCount = std::stod(next());
    else if (a == "--index-reference")
      base.indexReferenceCount = std::stod(next());
    else if (a == "--radius")
      base.coherenceRadius = std::stoi(next());
    else if (a == "--step")
      base.sparseStep = std::stoi(next());
    else if (a == "--k")
      base.k = std::stoi(next());
    else if (a == "--exhaustive-below")
      base.exhaustiveBelow = std::stoi(next());
    else if (a == "--exhaustive-budget")
      base.exhaustiveBudget = std::stod(next());
    else if (a == "--verbose")
      base.progress = [](const std::string& l, double) { std::cerr << l << "\n"; };
    else
      exemplars.push_back(a);
  }
  std::printf("%-12s %-9s %5s %8s %8s %8s %8s %8s %8s %8s %8s %8s %8s\n", "exemplar", "method", "size",
              "coh_ax", "com_ax", "coh_obl", "com_obl", "pd_ax", "pd_obl", "coverage", "colorTV", "time_s",
              "peakMiB");
  for (const auto& path : exemplars) {
    cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
    if (bgr.empty()) {
      std::cerr << "cannot read " << path << "\n";
      return 1;
    }
    cv::Mat rgb;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    rgb.convertTo(rgb, CV_32F, 1.0 / 255.0);
    std::string name = path.substr(path.find_last_of('/') + 1);
    name = name.substr(0, name.find('.'));
    for (const auto& m : methods) {
      solidtex::SynthesisOptions o = base;
      o.method = solidtex::parseMethod(m);
      o.exemplarName = name;
      const solidtex::SynthesisResult r = solidtex::synthesizeSolid(rgb, o);
      const double peak = solidtex::peakMemoryMiB();
      const solidtex::ContinuousQuality q =
          measure ? solidtex::measureContinuousSolid(r.volume, rgb) : solidtex::ContinuousQuality{};
      const double coverage = q.positions ? q.positions->coverage : 0.0;
      std::printf("%-12s %-9s %5d %8.4f %8.4f %8.4f %8.4f %8.4f %8.4f %8.3f %8.3f %8.2f %8.0f\n",
                  name.c_str(), m.c_str(), o.size, q.axis.coherence, q.axis.completeness, q.oblique.coherence,
                  q.oblique.completeness, q.axis.patchDistance, q.oblique.patchDistance, coverage,
                  q.colorHistogramDistance, r.statistics.seconds, peak);
      std::fflush(stdout);
      if (!reportDir.empty())
        std::ofstream(reportDir + "/" + name + "_" + m + "_" + std::to_string(o.size) + ".json")
            << solidtex::synthesisReport(o, r.statistics, measure ? &q : nullptr).dump(2);
      if (!slicesDir.empty())
        writeSlices(r.volume, slicesDir + "/" + name + "_" + m + "_" + std::to_string(o.size) + ".png");
    }
  }
  return 0;
}
