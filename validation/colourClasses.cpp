#include "validation/colourClasses.h"

#include <algorithm>
#include <numeric>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <opencv2/core.hpp>

#include "common/Error.h"
#include "segmentation/detail/color.h"

namespace solidtex {
namespace {

constexpr int kMaxClasses = 8;

int nearest(const float* lab, const cv::Mat& centres) {
  int best = 0;
  float bestDistance = 0;
  for (int c = 0; c < centres.rows; ++c) {
    const float* m = centres.ptr<float>(c);
    const float d = (lab[0] - m[0]) * (lab[0] - m[0]) + (lab[1] - m[1]) * (lab[1] - m[1]) +
                    (lab[2] - m[2]) * (lab[2] - m[2]);
    if (c == 0 || d < bestDistance) best = c, bestDistance = d;
  }
  return best;
}

}  // namespace

ColourClasses colourClasses(const cv::Mat& photo, int classes, std::uint64_t seed) {
  if (classes < 2 || classes > kMaxClasses) throw OptionError("--phases must be in [2, 8]");
  if (photo.type() != CV_32FC3) throw InputError("colour classes need a CV_32FC3 photo");
  const cv::Mat lab = segmentation::detail::linearToLab(segmentation::detail::srgbToLinear(photo));
  const cv::Mat samples = lab.reshape(1, int(lab.total()));
  if (samples.rows < classes) throw InputError("the photo has fewer pixels than --phases");
  cv::Mat labels, centres;
  cv::theRNG().state = seed == 0 ? 1 : seed;  // k-means++ draws from OpenCV's thread's generator
  cv::kmeans(samples, classes, labels,
             cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4), 3,
             cv::KMEANS_PP_CENTERS, centres);
  std::vector<int> order(static_cast<std::size_t>(classes));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return centres.at<float>(a, 0) < centres.at<float>(b, 0); });
  std::vector<int> rank(static_cast<std::size_t>(classes));
  ColourClasses out;
  out.centres.create(classes, 3, CV_32F);
  for (int r = 0; r < classes; ++r) {
    rank[std::size_t(order[std::size_t(r)])] = r;
    centres.row(order[std::size_t(r)]).copyTo(out.centres.row(r));
  }
  out.labels.create(photo.rows, photo.cols, CV_32S);
  for (int i = 0; i < labels.rows; ++i)
    out.labels.at<std::int32_t>(i / photo.cols, i % photo.cols) = rank[std::size_t(labels.at<int>(i))];
  return out;
}

ColourClasses colourClassesOfLabels(const cv::Mat& photo, const cv::Mat& labelImage,
                                    const std::string& name) {
  if (photo.type() != CV_32FC3 || labelImage.type() != CV_32FC3)
    throw InputError("colour classes need CV_32FC3 photo and labels");
  if (labelImage.size() != photo.size())
    throw InputError(name + " is " + std::to_string(labelImage.cols) + "x" + std::to_string(labelImage.rows) +
                     " but the photo is " + std::to_string(photo.cols) + "x" + std::to_string(photo.rows));
  cv::Mat bytes;
  labelImage.convertTo(bytes, CV_8UC3, 255.0);
  std::vector<std::uint32_t> packed(bytes.total());
  for (int i = 0; i < bytes.rows; ++i)
    for (int j = 0; j < bytes.cols; ++j) {
      const cv::Vec3b v = bytes.at<cv::Vec3b>(i, j);  // loadPhoto's channels are R, G, B
      packed[std::size_t(i) * std::size_t(bytes.cols) + std::size_t(j)] =
          (std::uint32_t(v[0]) << 16) | (std::uint32_t(v[1]) << 8) | v[2];
    }
  std::vector<std::uint32_t> values = packed;
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  if (values.size() < 2 || values.size() > std::size_t(kMaxClasses))
    throw InputError(name + " has " + std::to_string(values.size()) +
                     " distinct values; a phase mask needs 2 to 8");
  const cv::Mat lab = segmentation::detail::linearToLab(segmentation::detail::srgbToLinear(photo));
  ColourClasses out;
  out.labels.create(photo.rows, photo.cols, CV_32S);
  out.centres = cv::Mat::zeros(int(values.size()), 3, CV_32F);
  std::vector<double> sums(3 * values.size(), 0.0), counts(values.size(), 0.0);
  for (std::size_t p = 0; p < packed.size(); ++p) {
    const auto c = std::size_t(std::lower_bound(values.begin(), values.end(), packed[p]) - values.begin());
    out.labels.ptr<std::int32_t>(0)[p] = int(c);
    const float* l = lab.ptr<float>(0) + 3 * p;
    for (std::size_t k = 0; k < 3; ++k) sums[3 * c + k] += l[k];
    ++counts[c];
  }
  for (std::size_t c = 0; c < values.size(); ++c)
    for (std::size_t k = 0; k < 3; ++k)
      out.centres.at<float>(int(c), int(k)) = float(sums[3 * c + k] / counts[c]);
  return out;
}

std::vector<std::uint8_t> nearestClasses(const std::vector<Rgb>& linear, const cv::Mat& centres) {
  std::vector<std::uint8_t> out(linear.size());
  constexpr std::size_t kRun = 4096;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, (linear.size() + kRun - 1) / kRun),
                    [&](const tbb::blocked_range<std::size_t>& runs) {
                      for (std::size_t run = runs.begin(); run != runs.end(); ++run) {
                        const std::size_t from = run * kRun, n = std::min(kRun, linear.size() - from);
                        cv::Mat colours(1, int(n), CV_32FC3, const_cast<Rgb*>(linear.data() + from));
                        const cv::Mat lab = segmentation::detail::linearToLab(colours);
                        for (std::size_t i = 0; i < n; ++i)
                          out[from + i] = std::uint8_t(nearest(lab.ptr<float>(0) + 3 * i, centres));
                      }
                    });
  return out;
}

}  // namespace solidtex
