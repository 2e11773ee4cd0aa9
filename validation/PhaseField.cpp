#include "validation/PhaseField.h"

#include <numeric>

#include "common/Error.h"

namespace solidtex {

double PhaseField::fraction() const {
  if (inside.empty()) return 0;
  return double(std::accumulate(inside.begin(), inside.end(), std::size_t(0))) / double(inside.size());
}

PhaseField phaseOfIds(const Dims& dims, const std::vector<std::int32_t>& ids, bool particles) {
  PhaseField field{dims, std::vector<std::uint8_t>(ids.size())};
  for (std::size_t i = 0; i < ids.size(); ++i) field.inside[i] = (ids[i] > 0) == particles;
  return field;
}

PhaseField phaseOfLabels(const cv::Mat& labels, bool particles) {
  if (labels.type() != CV_32S) throw InputError("a label image must be CV_32S");
  PhaseField field{{labels.cols, labels.rows, 1}, std::vector<std::uint8_t>(labels.total())};
  std::size_t i = 0;
  for (int y = 0; y < labels.rows; ++y)
    for (int x = 0; x < labels.cols; ++x)
      field.inside[i++] = (labels.at<std::int32_t>(y, x) > 0) == particles;
  return field;
}

}  // namespace solidtex
