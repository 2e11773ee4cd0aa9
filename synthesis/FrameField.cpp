#include "synthesis/FrameField.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Geometry>

#include "common/Error.h"

namespace solidtex {
namespace {

void requirePositive(const Dims& dims, const std::string& what) {
  if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0)
    throw InputError(what + ": the field's size must be positive, not " + std::to_string(dims.x) + "x" +
                     std::to_string(dims.y) + "x" + std::to_string(dims.z));
}

/// A rotation about z by `radians`: exemplar x -> (cos, sin, 0), exemplar y -> (-sin, cos, 0).
Eigen::Matrix3f turnXY(double radians) {
  return Eigen::AngleAxisf(float(radians), Eigen::Vector3f::UnitZ()).toRotationMatrix();
}

/// The frame whose exemplar y axis is `normal` (in the XY plane, not normalised), x = y rotated -90
/// degrees (so x cross y = z), z = z. Identity for a zero normal.
Eigen::Matrix3f frameWithNormal(double nx, double ny) {
  const double length = std::hypot(nx, ny);
  if (length == 0) return Eigen::Matrix3f::Identity();
  const float cx = float(nx / length), cy = float(ny / length);
  Eigen::Matrix3f m;
  m << cy, cx, 0,  //
      -cx, cy, 0,  //
      0, 0, 1;
  return m;
}

/// Fills `field` slice by slice from `frame(i, j, k)`.
template <typename Frame>
FrameField fill(const Dims& dims, Frame frame) {
  FrameField field;
  field.dims = dims;
  field.axes.resize(dims.count());
  tbb::parallel_for(tbb::blocked_range<int>(0, dims.z), [&](const tbb::blocked_range<int>& ks) {
    for (int k = ks.begin(); k < ks.end(); ++k)
      for (int j = 0; j < dims.y; ++j)
        for (int i = 0; i < dims.x; ++i) field.axes[dims.index(i, j, k)] = frame(i, j, k);
  });
  return field;
}

}  // namespace

const std::vector<std::string>& builtinFrameFieldNames() {
  static const std::vector<std::string> names{"circle", "oval", "slant", "zigzag", "slant3d"};
  return names;
}

FrameField builtinFrameField(const std::string& name, const Dims& dims) {
  requirePositive(dims, "frame field \"" + name + "\"");
  const double cx = (dims.x - 1) / 2.0, cy = (dims.y - 1) / 2.0;
  constexpr double kQuarterPi = std::numbers::pi / 4;
  if (name == "circle") return fill(dims, [&](int i, int j, int) { return frameWithNormal(i - cx, j - cy); });
  if (name == "oval")  // the normal of (dx / 2)^2 + dy^2: (dx / 4, dy), scaled by 4
    return fill(dims, [&](int i, int j, int) { return frameWithNormal(i - cx, 4 * (j - cy)); });
  if (name == "slant") {
    const Eigen::Matrix3f turn = turnXY(kQuarterPi);
    return fill(dims, [&](int, int, int) { return turn; });
  }
  if (name == "zigzag") {
    const int half = std::max(4, int(std::lround(dims.x / 8.0)));
    const Eigen::Matrix3f up = turnXY(kQuarterPi), down = turnXY(-kQuarterPi);
    return fill(dims, [&](int i, int, int) { return (i / half) % 2 == 0 ? up : down; });
  }
  if (name == "slant3d") {
    const Eigen::Matrix3f tilt =
        Eigen::AngleAxisf(float(kQuarterPi), Eigen::Vector3f(1, 1, 0).normalized()).toRotationMatrix();
    return fill(dims, [&](int, int, int) { return tilt; });
  }
  std::string valid;
  for (const auto& n : builtinFrameFieldNames()) valid += (valid.empty() ? "" : ", ") + n;
  throw OptionError("unknown frame field \"" + name + "\" (valid: " + valid + ")");
}

}  // namespace solidtex
