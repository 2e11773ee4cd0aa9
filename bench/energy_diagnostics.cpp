// How the slice energy (eq. 1, gamma 0.8) ranks reference volumes: does it prefer blur or flat colour?
//   energy_diagnostics baselines SIZE EXEMPLAR.png...   uniform mean colour (and snapped to the nearest
//                                                       exemplar pixel), i.i.d. random pixels (sharp and
//                                                       blurred), the exemplar extruded along z
//   energy_diagnostics chen-wang SIZE EXEMPLAR.png...   chen-wang's volume as is and blurred (sigma 0.5-1.0)
//   energy_diagnostics kopf SIZE EXEMPLAR.png...        kopf's volume as is and snapped voxel by voxel to
//                                                       the nearest exemplar colour
// Seed 1 (the output does not depend on the thread count). Each line: E axis/oblique, the squared forms,
// position coverage (-1: no sources), colour TV.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "synthesis/detail/ExemplarPyramid.h"
#include "synthesis/detail/solidMeasures.h"
#include "synthesis/detail/upsample.h"
#include "synthesis/synthesizeSolid.h"

using namespace solidtex;
using namespace solidtex::synthesis;

namespace {

/// Separable periodic Gaussian blur of the colours (sources kept).
WorkVolume blur(const WorkVolume& v, double sigma) {
  const int r = int(std::ceil(3 * sigma));
  std::vector<float> k(2 * r + 1);
  float sum = 0;
  for (int i = -r; i <= r; ++i) sum += k[i + r] = float(std::exp(-0.5 * i * i / (sigma * sigma)));
  for (float& x : k) x /= sum;
  WorkVolume a = v, b = v;
  for (int axis = 0; axis < 3; ++axis) {
    for (int z = 0; z < v.n; ++z)
      for (int y = 0; y < v.n; ++y)
        for (int x = 0; x < v.n; ++x) {
          float acc[3] = {0, 0, 0};
          for (int i = -r; i <= r; ++i) {
            int c[3] = {x, y, z};
            c[axis] = v.wrap(c[axis] + i);
            const float* p = a.at(a.index(c[0], c[1], c[2]));
            for (int q = 0; q < 3; ++q) acc[q] += k[i + r] * p[q];
          }
          std::copy(acc, acc + 3, b.at(b.index(x, y, z)));
        }
    std::swap(a, b);
  }
  return a;
}

/// Every voxel replaced by the exemplar pixel nearest in colour (its source set to that pixel).
WorkVolume snap(const WorkVolume& v, const RgbImage& ex) {
  WorkVolume o = v;
  o.source.assign(v.count(), -1);
  const int P = ex.pixelCount();
  int bp = 0;
  for (std::size_t i = 0; i < v.count(); ++i) {
    const float* c = v.at(i);
    if (i > 0 && std::equal(c, c + 3, v.at(i - 1))) {  // same colour as the previous voxel: same pixel
      std::copy(o.at(i - 1), o.at(i - 1) + 3, o.at(i));
      o.source[i] = bp;
      continue;
    }
    float best = 1e30f;
    for (int p = 0; p < P; ++p) {
      const float* e = ex.data.data() + 3 * std::size_t(p);
      const float d =
          (c[0] - e[0]) * (c[0] - e[0]) + (c[1] - e[1]) * (c[1] - e[1]) + (c[2] - e[2]) * (c[2] - e[2]);
      if (d < best) best = d, bp = p;
    }
    std::copy(ex.data.data() + 3 * std::size_t(bp), ex.data.data() + 3 * std::size_t(bp) + 3, o.at(i));
    o.source[i] = bp;
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: energy_diagnostics baselines|chen-wang|kopf SIZE EXEMPLAR.png...\n");
    return 2;
  }
  const std::string mode = argv[1];
  const int size = std::stoi(argv[2]);
  for (int a = 3; a < argc; ++a) {
    cv::Mat bgr = cv::imread(argv[a]), rgb;
    if (bgr.empty()) {
      std::fprintf(stderr, "cannot read %s\n", argv[a]);
      return 1;
    }
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    rgb.convertTo(rgb, CV_32F, 1 / 255.0);
    const RgbImage ex = toRgbImage(rgb);
    auto show = [&](const std::string& what, const WorkVolume& w) {
      const SliceEnergy e = sliceEnergy(w, ex);
      const double coverage =
          w.source.empty() ? -1 : positionHistogramStats(w.source, ex.pixelCount()).coverage;
      std::printf("%s %s %s E %.4f %.4f E2 %.5f %.5f coverage %.3f colourTV %.3f\n", argv[a], mode.c_str(),
                  what.c_str(), e.axis, e.oblique, e.axisSquared, e.obliqueSquared, coverage,
                  colorHistogramDistance(w.rgb.data(), w.count(), ex));
      std::fflush(stdout);
    };
    if (mode == "baselines") {
      WorkVolume u;
      u.n = size;
      u.rgb.resize(u.count() * 3);
      double mean[3] = {0, 0, 0};
      for (int p = 0; p < ex.pixelCount(); ++p)
        for (int c = 0; c < 3; ++c) mean[c] += ex.data[3 * std::size_t(p) + c] / double(ex.pixelCount());
      for (std::size_t i = 0; i < u.count(); ++i)
        for (int c = 0; c < 3; ++c) u.rgb[3 * i + c] = float(mean[c]);
      show("uniform-mean-colour", u);
      show("uniform-mean-colour-snapped", snap(u, ex));
      const WorkVolume r = randomVolume(size, ex, 7);
      show("iid-random-pixels", r);
      show("iid-random-pixels-blur1.0", blur(r, 1.0));
      WorkVolume x = r;
      for (int z = 0; z < size; ++z)
        for (int y = 0; y < size; ++y)
          for (int xx = 0; xx < size; ++xx)
            x.source[x.index(xx, y, z)] = (y % ex.height) * ex.width + (xx % ex.width);
      colorsFromSources(x, ex);
      show("exemplar-extruded-along-z", x);
      continue;
    }
    SynthesisOptions o;
    o.method = parseMethod(mode);
    o.size = size;
    const SynthesisResult result = synthesizeSolid(rgb, o);
    const WorkVolume v = srgbVolumeOf(result.volume, ex.width);
    show("as-is", v);
    if (o.method == Method::Kopf) {
      show("snapped", snap(v, ex));
      continue;
    }
    for (double sigma : {0.5, 0.7, 1.0}) show("blur" + std::to_string(sigma).substr(0, 3), blur(v, sigma));
  }
  return 0;
}
