#include "validation/tortuosity.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

#include <tbb/task_arena.h>
#include <Eigen/IterativeLinearSolvers>
#include <Eigen/SparseCore>

#include "common/Error.h"
#include "common/secondsSince.h"
#include "validation/aggregationMultigrid.h"

namespace solidtex {
namespace {

// 32-bit indices: a quarter less to read per product than 64-bit ones, enough below 300 M unknowns.
using Matrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

const char* axisName(int axis) { return axis == 0 ? "x" : axis == 1 ? "y" : "z"; }

// The phase's voxels joined through face neighbours to the face where coordinate `axis` is `layer`.
std::vector<std::uint8_t> joinedToFace(const PhaseField& phase, int axis, int layer) {
  const Dims& d = phase.dims;
  std::vector<std::uint8_t> joined(phase.inside.size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t i = 0; i < phase.inside.size(); ++i) {
    const Voxel v = d.voxel(i);
    const std::array<int, 3> c{v.x, v.y, v.z};
    if (c[std::size_t(axis)] == layer && phase.inside[i]) joined[i] = 1, stack.push_back(i);
  }
  while (!stack.empty()) {
    const Voxel v = d.voxel(stack.back());
    stack.pop_back();
    for (const Voxel& s : {Voxel{1, 0, 0}, Voxel{-1, 0, 0}, Voxel{0, 1, 0}, Voxel{0, -1, 0}, Voxel{0, 0, 1},
                           Voxel{0, 0, -1}}) {
      const Voxel w{v.x + s.x, v.y + s.y, v.z + s.z};
      if (!d.contains(w.x, w.y, w.z)) continue;
      const std::size_t j = d.index(w);
      if (phase.inside[j] && !joined[j]) joined[j] = 1, stack.push_back(j);
    }
  }
  return joined;
}

struct DiffusionSystem {
  Matrix conductance;
  Eigen::VectorXd source, guess;
  std::vector<std::int64_t> unknown;  // per voxel, -1 where no unknown
  std::vector<std::size_t> voxel;     // per unknown
};

// Unit conductance between face neighbours, 2 to the reservoirs half a voxel beyond the faces;
// the guess linear across the axis.
DiffusionSystem diffusionSystem(const PhaseField& phase, const std::vector<std::uint8_t>& active, int axis) {
  const Dims& d = phase.dims;
  const std::array<int, 3> n{d.x, d.y, d.z};
  DiffusionSystem s;
  s.unknown.assign(active.size(), -1);
  for (std::size_t i = 0; i < active.size(); ++i)
    if (active[i]) s.unknown[i] = std::int64_t(s.voxel.size()), s.voxel.push_back(i);
  const auto m = Eigen::Index(s.voxel.size());
  s.source = Eigen::VectorXd::Zero(m);
  s.guess.resize(m);
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(s.voxel.size() * 7);
  for (Eigen::Index row = 0; row < m; ++row) {
    const Voxel v = d.voxel(s.voxel[std::size_t(row)]);
    const std::array<int, 3> c{v.x, v.y, v.z};
    double diagonal = 0;
    for (int a = 0; a < 3; ++a)
      for (int step : {-1, 1}) {
        std::array<int, 3> w = c;
        w[std::size_t(a)] += step;
        if (d.contains(w[0], w[1], w[2])) {
          const std::int64_t col = s.unknown[d.index(w[0], w[1], w[2])];
          if (col >= 0) entries.emplace_back(int(row), int(col), -1.0), diagonal += 1;
        } else if (a == axis) {
          diagonal += 2;
          if (step < 0) s.source[row] = 2;
        }
      }
    entries.emplace_back(int(row), int(row), diagonal);
    s.guess[row] = 1.0 - (c[std::size_t(axis)] + 0.5) / n[std::size_t(axis)];
  }
  s.conductance.resize(m, m);
  s.conductance.setFromTriplets(entries.begin(), entries.end());
  return s;
}

// The voxels of the phase joined to both faces across `axis`.
std::vector<std::uint8_t> joinedToBothFaces(const PhaseField& phase, int axis) {
  const std::array<int, 3> n{phase.dims.x, phase.dims.y, phase.dims.z};
  std::vector<std::uint8_t> active = joinedToFace(phase, axis, 0);
  const std::vector<std::uint8_t> outlet = joinedToFace(phase, axis, n[std::size_t(axis)] - 1);
  for (std::size_t i = 0; i < active.size(); ++i) active[i] = active[i] && outlet[i];
  return active;
}

struct Solve {
  std::vector<double> concentration;  // per voxel, NaN where no unknown
  int iterations = 0;
  double residual = 0;
};

// The steady concentration over the active voxels, by conjugate gradients preconditioned with
// aggregation multigrid: Jacobi's preconditioner needed 1600 iterations on touching particles at
// 256^3, the multigrid cycle 41, at a few times the work each.
Solve steadyConcentration(const PhaseField& phase, const std::vector<std::uint8_t>& active, int axis,
                          double tolerance, int maxIterations) {
  const Dims& d = phase.dims;
  const DiffusionSystem system = diffusionSystem(phase, active, axis);
  Eigen::ConjugateGradient<Matrix, Eigen::Lower | Eigen::Upper, AggregationMultigrid> solver;
  solver.setTolerance(tolerance);
  solver.setMaxIterations(maxIterations);
  std::vector<Voxel> voxels(system.voxel.size());
  for (std::size_t u = 0; u < voxels.size(); ++u) voxels[u] = d.voxel(system.voxel[u]);
  solver.preconditioner().setVoxels(std::move(voxels));
  solver.compute(system.conductance);
  const Eigen::VectorXd c = solver.solveWithGuess(system.source, system.guess);
  Solve out{std::vector<double>(d.count(), std::nan("")), int(solver.iterations()), solver.error()};
  for (std::size_t u = 0; u < system.voxel.size(); ++u)
    out.concentration[system.voxel[u]] = c[Eigen::Index(u)];
  return out;
}

}  // namespace

Tortuosity tortuosityFactor(const PhaseField& phase, int axis, const TortuosityOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const std::array<int, 3> n{phase.dims.x, phase.dims.y, phase.dims.z};
  if (axis < 0 || axis > 2 || n[std::size_t(axis)] < 1 || (phase.isImage() && axis == 2))
    throw OptionError("tortuosity: no such axis in this field");
  const int last = n[std::size_t(axis)] - 1;
  const std::vector<std::uint8_t> active = joinedToBothFaces(phase, axis);
  std::size_t joined = 0, phaseVoxels = 0;
  for (std::size_t i = 0; i < active.size(); ++i) {
    joined += active[i];
    phaseVoxels += phase.inside[i];
  }
  if (joined == 0)
    throw InputError(std::string("tortuosity: the phase does not join the faces across ") + axisName(axis));
  if (joined >= std::size_t(std::numeric_limits<int>::max() / 8))
    throw InputError("tortuosity: the phase has too many voxels for one solve");
  Eigen::setNbThreads(tbb::this_task_arena::max_concurrency());
  const Solve solve = steadyConcentration(
      phase, active, axis, options.tolerance,
      options.maxIterations > 0 ? options.maxIterations : 10 * std::max({n[0], n[1], n[2]}) + 1000);

  double inflow = 0, outflow = 0;
  for (std::size_t i = 0; i < solve.concentration.size(); ++i) {
    const double c = solve.concentration[i];
    if (std::isnan(c)) continue;
    const Voxel v = phase.dims.voxel(i);
    const int at = axis == 0 ? v.x : axis == 1 ? v.y : v.z;
    if (at == 0) inflow += 2 * (1 - c);
    if (at == last) outflow += 2 * c;
  }
  Tortuosity out;
  out.axis = axis;
  out.fraction = double(phaseVoxels) / double(phase.inside.size());
  const double area = double(phase.inside.size()) / n[std::size_t(axis)];
  out.effectiveDiffusivity = 0.5 * (inflow + outflow) * n[std::size_t(axis)] / area;
  out.factor = out.fraction / out.effectiveDiffusivity;
  out.connectedFraction = double(joined) / double(phaseVoxels);
  out.iterations = solve.iterations;
  out.residual = solve.residual;
  out.fluxMismatch = inflow > 0 ? std::abs(inflow - outflow) / inflow : 0.0;
  out.seconds = secondsSince(start);
  return out;
}

}  // namespace solidtex
