#include "molmesh/volume/ball_union.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/volume/grid_lattice.hpp"

namespace molmesh {

Grid ball_union_grid(const Atoms& atoms, double grow, double spacing, int margin_cells,
                     double max_memory_bytes, double bytes_per_sample) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw Error("the grid spacing must be positive, got " + std::to_string(spacing));
  if (!(grow >= 0.0) || !std::isfinite(grow))
    throw Error("the probe radius must be >= 0, got " + std::to_string(grow));
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 hi = -lo;
  for (const Atom& atom : atoms) {
    if (!(atom.radius > 0.0)) continue;
    const double r = atom.radius + grow;
    lo = lo.cwiseMin(atom.center - Vec3::Constant(r));
    hi = hi.cwiseMax(atom.center + Vec3::Constant(r));
  }
  if (!(lo.x() <= hi.x())) throw Error("no atom has a positive radius: the surface is empty");
  return lattice_around(lo, hi, spacing, margin_cells, max_memory_bytes, bytes_per_sample);
}

void ball_union_onto(const Atoms& atoms, double grow, Grid& grid, const Reporter& reporter) {
  const double h = grid.spacing.maxCoeff();
  const double floor_value = -2.0 * h;
  allocate_values(grid, floor_value);
  // Atoms whose reach (ball + two cells) touches each z-plane; a plane is written by one
  // task only, and max() is exact and order-free, so the result is thread-count independent.
  const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  std::vector<std::vector<int>> plane_atoms(static_cast<std::size_t>(nz));
  for (std::size_t n = 0; n < atoms.size(); ++n) {
    if (!(atoms[n].radius > 0.0)) continue;
    const double reach = atoms[n].radius + grow - floor_value;
    const double c = (atoms[n].center.z() - grid.origin.z()) / grid.spacing.z();
    const int k0 = std::max(0, static_cast<int>(std::ceil(c - reach / grid.spacing.z())));
    const int k1 = std::min(nz - 1, static_cast<int>(std::floor(c + reach / grid.spacing.z())));
    for (int k = k0; k <= k1; ++k) plane_atoms[static_cast<std::size_t>(k)].push_back(int(n));
  }
  reporter.progress("distance field", 0.0);
  tbb::parallel_for(tbb::blocked_range<int>(0, nz, 1), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k) {
      const double z = grid.origin.z() + k * grid.spacing.z();
      for (int n : plane_atoms[static_cast<std::size_t>(k)]) {
        const Atom& atom = atoms[static_cast<std::size_t>(n)];
        const double radius = atom.radius + grow;
        const double reach = radius - floor_value;
        const double dz = z - atom.center.z();
        const double rest_z = reach * reach - dz * dz;
        if (rest_z < 0.0) continue;
        const double ry = std::sqrt(rest_z);
        const double cy = (atom.center.y() - grid.origin.y()) / grid.spacing.y();
        const int j0 = std::max(0, static_cast<int>(std::ceil(cy - ry / grid.spacing.y())));
        const int j1 = std::min(ny - 1, static_cast<int>(std::floor(cy + ry / grid.spacing.y())));
        for (int j = j0; j <= j1; ++j) {
          const double dy = grid.origin.y() + j * grid.spacing.y() - atom.center.y();
          const double rest = rest_z - dy * dy;
          if (rest < 0.0) continue;
          const double rx = std::sqrt(rest);
          const double cx = (atom.center.x() - grid.origin.x()) / grid.spacing.x();
          const int i0 = std::max(0, static_cast<int>(std::ceil(cx - rx / grid.spacing.x())));
          const int i1 = std::min(nx - 1, static_cast<int>(std::floor(cx + rx / grid.spacing.x())));
          double* row = grid.values.data() + grid.index(0, j, k);
          const double d2yz = dy * dy + dz * dz;
          for (int i = i0; i <= i1; ++i) {
            const double dx = grid.origin.x() + i * grid.spacing.x() - atom.center.x();
            const double d2 = dx * dx + d2yz;
            // value = radius - sqrt(d2) beats row[i] only if sqrt(d2) < radius - row[i]: most
            // samples (inside several balls) are rejected on the squares, with a margin far
            // beyond rounding so the exact comparison decides every close call.
            const double gap = radius - row[i];
            if (!(gap > 0.0) || d2 > gap * gap * (1.0 + 1e-9)) continue;
            const double value = radius - std::sqrt(d2);
            if (value > row[i]) row[i] = value;
          }
        }
      }
    }
  });
  reporter.progress("distance field", 1.0);
}

Grid ball_union_field(const Atoms& atoms, double grow, double spacing, const Reporter& reporter,
                      double max_memory_bytes) {
  Grid grid = ball_union_grid(atoms, grow, spacing, 3, max_memory_bytes);
  ball_union_onto(atoms, grow, grid, reporter);
  return grid;
}

}  // namespace molmesh
