#include "segmentation/detail/flattenShading.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace solidtex::segmentation::detail {
namespace {

constexpr int kTerms = 6;               // 1, x, y, x^2, xy, y^2
constexpr double kMinExplained = 0.25;  // share of background variance the surface must explain
constexpr double kMinShare = 0.02;      // background share of the image needed for a fit
constexpr double kSamples = 65536;      // pixels the fit looks at, at most about

using Terms = std::array<double, kTerms>;

Terms terms(int x, int y, const cv::Size& size) {
  // Coordinates in [-1, 1] keep the normal equations well conditioned at any image size.
  const double u = 2.0 * x / std::max(1, size.width - 1) - 1, v = 2.0 * y / std::max(1, size.height - 1) - 1;
  return {1, u, v, u * u, u * v, v * v};
}

struct Fit {
  cv::Matx<double, kTerms, 3> coefficients;
  cv::Vec3d explained;  // R^2 per channel
};

// A smooth six-term surface needs no more than about kSamples evenly spread pixels.
int sampleStride(const cv::Size& size) {
  return std::max(1, int(std::ceil(std::sqrt(double(size.area()) / kSamples))));
}

Fit fitSurface(const cv::Mat& lab, const cv::Mat& mask) {
  cv::Matx<double, kTerms, kTerms> normal = cv::Matx<double, kTerms, kTerms>::zeros();
  cv::Matx<double, kTerms, 3> rhs = cv::Matx<double, kTerms, 3>::zeros();
  cv::Vec3d sum(0, 0, 0), sumSq(0, 0, 0);
  double n = 0;
  const int stride = sampleStride(lab.size());
  for (int y = 0; y < lab.rows; y += stride) {
    const auto* p = lab.ptr<cv::Vec3f>(y);
    const uchar* m = mask.ptr<uchar>(y);
    for (int x = 0; x < lab.cols; x += stride) {
      if (!m[x]) continue;
      const Terms t = terms(x, y, lab.size());
      for (int i = 0; i < kTerms; ++i) {
        for (int j = 0; j < kTerms; ++j) normal(i, j) += t[i] * t[j];
        for (int c = 0; c < 3; ++c) rhs(i, c) += t[i] * p[x][c];
      }
      for (int c = 0; c < 3; ++c) sum[c] += p[x][c], sumSq[c] += double(p[x][c]) * p[x][c];
      n += 1;
    }
  }
  Fit fit;
  fit.coefficients = normal.solve(rhs, cv::DECOMP_SVD);
  // R^2 = 1 - residual / total, with residual = sum f^2 - coef . rhs for least squares.
  for (int c = 0; c < 3; ++c) {
    double explainedSq = 0;
    for (int i = 0; i < kTerms; ++i) explainedSq += fit.coefficients(i, c) * rhs(i, c);
    const double total = sumSq[c] - sum[c] * sum[c] / n;
    const double residual = sumSq[c] - explainedSq;
    fit.explained[c] = total > 1e-9 ? 1.0 - residual / total : 0.0;
  }
  return fit;
}

}  // namespace

cv::Mat flattenShading(const cv::Mat& lab, const cv::Mat& backgroundMask) {
  CV_Assert(lab.type() == CV_32FC3 && backgroundMask.type() == CV_8UC1 &&
            lab.size() == backgroundMask.size());
  if (cv::countNonZero(backgroundMask) < kMinShare * double(lab.total()) + kTerms) return lab.clone();
  const Fit fit = fitSurface(lab, backgroundMask);
  const cv::Scalar mean = cv::mean(lab, backgroundMask);
  cv::Mat flat = lab.clone();
  for (int y = 0; y < flat.rows; ++y) {
    auto* p = flat.ptr<cv::Vec3f>(y);
    for (int x = 0; x < flat.cols; ++x) {
      const Terms t = terms(x, y, flat.size());
      for (int c = 0; c < 3; ++c) {
        if (fit.explained[c] < kMinExplained) continue;
        double surface = 0;
        for (int i = 0; i < kTerms; ++i) surface += fit.coefficients(i, c) * t[i];
        p[x][c] = float(p[x][c] - surface + mean[c]);
      }
    }
  }
  return flat;
}

}  // namespace solidtex::segmentation::detail
