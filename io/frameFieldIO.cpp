#include "io/frameFieldIO.h"

#include <limits>
#include <stdexcept>

#include <openvdb/openvdb.h>
#include <openvdb/tools/Dense.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include "common/Error.h"
#include "io/detail/vdbGrids.h"

namespace solidtex {
namespace {

const char* const kAxisGridNames[3] = {"axis_x", "axis_y", "axis_z"};

void requirePositive(const Dims& dims, const std::string& what) {
  if (dims.x <= 0 || dims.y <= 0 || dims.z <= 0)
    throw InputError(what + ": the field's size must be positive, not " + std::to_string(dims.x) + "x" +
                     std::to_string(dims.y) + "x" + std::to_string(dims.z));
}

openvdb::CoordBBox boxOf(const Dims& dims) {
  return openvdb::CoordBBox(openvdb::Coord(0, 0, 0), openvdb::Coord(dims.x - 1, dims.y - 1, dims.z - 1));
}

std::string boxName(const openvdb::CoordBBox& box) {
  if (box.empty()) return "none";
  const openvdb::Coord lo = box.min(), hi = box.max();
  return "(" + std::to_string(lo.x()) + "," + std::to_string(lo.y()) + "," + std::to_string(lo.z()) +
         ") to (" + std::to_string(hi.x()) + "," + std::to_string(hi.y()) + "," + std::to_string(hi.z()) +
         ")";
}

using DenseVec3 = openvdb::tools::Dense<openvdb::Vec3s, openvdb::tools::LayoutXYZ>;

std::string voxelName(const Voxel& v) {
  return "(" + std::to_string(v.x) + "," + std::to_string(v.y) + "," + std::to_string(v.z) + ")";
}

enum class FrameProblem { None, ZeroAxis, Parallel };

/// The rotation nearest to the frame `m` (columns normalised; left-handed: exemplar z negated): the polar
/// factor a (a^T a)^(-1/2), from the eigen decomposition of a^T a (the squared singular values).
FrameProblem orthonormalise(const Eigen::Matrix3f& m, Eigen::Matrix3f& out) {
  Eigen::Matrix3d a = m.cast<double>();
  if (!a.allFinite()) return FrameProblem::ZeroAxis;
  for (int c = 0; c < 3; ++c) {
    const double length = a.col(c).norm();
    if (length < 1e-6) return FrameProblem::ZeroAxis;
    a.col(c) /= length;
  }
  if (a.determinant() < 0) a.col(2) = -a.col(2);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(a.transpose() * a);
  const Eigen::Vector3d squared = eigen.eigenvalues();  // ascending
  if (eigen.info() != Eigen::Success || !(squared(0) >= 1e-6)) return FrameProblem::Parallel;
  const Eigen::Matrix3d& v = eigen.eigenvectors();
  out = (a * v * squared.cwiseSqrt().cwiseInverse().asDiagonal() * v.transpose()).cast<float>();
  return FrameProblem::None;
}

}  // namespace

FrameField readFrameField(const std::string& path, const Dims& dims) {
  requirePositive(dims, "cannot read " + path);
  const io::detail::VdbContents contents = io::detail::readVdbGrids(path);
  openvdb::Vec3SGrid::Ptr grids[3];
  for (int a = 0; a < 3; ++a) {
    const auto grid = io::detail::findGrid(contents, kAxisGridNames[a]);
    if (!grid)
      throw InputError("cannot read " + path + ": no grid \"" + kAxisGridNames[a] +
                       "\" (a frame field needs Vec3SGrids axis_x, axis_y and axis_z)");
    grids[a] = openvdb::gridPtrCast<openvdb::Vec3SGrid>(grid);
    if (!grids[a])
      throw InputError("cannot read " + path + ": grid \"" + kAxisGridNames[a] + "\" is not a Vec3SGrid");
  }

  openvdb::CoordBBox covered;
  for (const auto& grid : grids) covered.expand(grid->evalActiveVoxelBoundingBox());
  if (covered != boxOf(dims))
    throw InputError("cannot read " + path + ": the field covers voxels " + boxName(covered) +
                     ", the output needs " + boxName(boxOf(dims)));

  FrameField field;
  field.dims = dims;
  field.axes.assign(dims.count(), Eigen::Matrix3f::Zero());
  {
    std::vector<openvdb::Vec3s> dense(dims.count());
    for (int a = 0; a < 3; ++a) {
      DenseVec3 wrapper(boxOf(dims), dense.data());
      openvdb::tools::copyToDense(*grids[a], wrapper);
      grids[a].reset();
      for (std::size_t v = 0; v < dense.size(); ++v)
        field.axes[v].col(a) = Eigen::Vector3f(dense[v].x(), dense[v].y(), dense[v].z());
    }
  }

  // The first bad voxel of each slice, so the error names the same voxel whatever the threads.
  constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
  std::vector<std::size_t> firstBad(std::size_t(dims.z), kNone);
  std::vector<FrameProblem> problems(std::size_t(dims.z), FrameProblem::None);
  tbb::parallel_for(tbb::blocked_range<int>(0, dims.z), [&](const tbb::blocked_range<int>& ks) {
    for (int k = ks.begin(); k < ks.end(); ++k) {
      const std::size_t begin = dims.index(0, 0, k), end = begin + std::size_t(dims.x) * std::size_t(dims.y);
      for (std::size_t v = begin; v < end; ++v) {
        Eigen::Matrix3f rotation;
        const FrameProblem problem = orthonormalise(field.axes[v], rotation);
        if (problem != FrameProblem::None) {
          firstBad[std::size_t(k)] = v;
          problems[std::size_t(k)] = problem;
          break;
        }
        field.axes[v] = rotation;
      }
    }
  });
  for (int k = 0; k < dims.z; ++k)
    if (firstBad[std::size_t(k)] != kNone)
      throw InputError("cannot read " + path + ": the frame at voxel " +
                       voxelName(dims.voxel(firstBad[std::size_t(k)])) +
                       (problems[std::size_t(k)] == FrameProblem::ZeroAxis
                            ? " has an axis of (near) zero length"
                            : " is degenerate (its axes are parallel or coplanar)"));
  return field;
}

void writeFrameField(const std::string& path, const FrameField& field) {
  openvdb::initialize();
  const Dims& dims = field.dims;
  requirePositive(dims, "cannot write " + path);
  if (field.axes.size() != dims.count())
    throw std::logic_error("writeFrameField: the axes do not match the field's dimensions");
  auto xform = openvdb::math::Transform::createLinearTransform(1.0);
  openvdb::GridPtrVec grids;
  std::vector<openvdb::Vec3s> dense(dims.count());
  for (int a = 0; a < 3; ++a) {
    for (std::size_t v = 0; v < dense.size(); ++v) {
      const auto& c = field.axes[v].col(a);
      dense[v] = openvdb::Vec3s(c.x(), c.y(), c.z());
    }
    auto grid = openvdb::Vec3SGrid::create(openvdb::Vec3s(0.f));
    // A negative tolerance keeps every voxel active, zero vectors included.
    openvdb::tools::copyFromDense(DenseVec3(boxOf(dims), dense.data()), *grid, openvdb::Vec3s(-1.f));
    grid->setName(kAxisGridNames[a]);
    grid->setTransform(xform);
    grid->setVectorType(openvdb::VEC_CONTRAVARIANT_RELATIVE);
    grids.push_back(grid);
  }
  io::detail::writeVdbGrids(path, grids);
}

}  // namespace solidtex
