#include "molmesh/volume/grid_lattice.hpp"

#include <cmath>
#include <cstdio>
#include <new>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/core/resource_limits.hpp"

namespace molmesh {
namespace {

std::string size_text(const std::array<double, 3>& extent) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%.0f x %.0f x %.0f", extent[0], extent[1], extent[2]);
  return buffer;
}

std::string size_text(const std::array<int, 3>& dims) {
  return size_text(std::array<double, 3>{double(dims[0]), double(dims[1]), double(dims[2])});
}

}  // namespace

Grid lattice_around(const Vec3& lo, const Vec3& hi, double h, int margin_cells,
                    double max_memory_bytes, double bytes_per_sample) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw Error("grid spacing must be a positive number of Å (got " + std::to_string(h) + ")");
  if (margin_cells < 0) throw Error("the grid margin must not be negative");
  Grid grid;
  grid.spacing = Vec3::Constant(h);
  std::array<double, 3> extent{};
  for (int axis = 0; axis < 3; ++axis) {
    const double first = std::floor(lo[axis] / h) - margin_cells;
    const double last = std::ceil(hi[axis] / h) + margin_cells;
    extent[axis] = last - first + 1;
    grid.origin[axis] = first * h;
  }
  char spacing[32];
  std::snprintf(spacing, sizeof spacing, "%g", h);
  check_memory(extent[0] * extent[1] * extent[2] * bytes_per_sample, max_memory_bytes,
               "the grid of " + size_text(extent) + " samples (spacing " + spacing + " Å)",
               "use a coarser `spacing`, or check the coordinates (atoms far apart)");
  if (extent[0] * extent[1] * extent[2] > kMaxGridSamples)
    throw Error("the grid of " + size_text(extent) +
                " samples is too large; use a coarser `spacing`");
  for (int axis = 0; axis < 3; ++axis) grid.dims[axis] = static_cast<int>(extent[axis]);
  return grid;
}

void allocate_values(Grid& grid, double fill) {
  try {
    grid.values.assign(grid.size(), fill);
  } catch (const std::bad_alloc&) {
    throw Error("not enough memory for a grid of " + size_text(grid.dims) +
                " samples; use a coarser `spacing`");
  }
}

bool reaches_boundary(const Grid& grid, double isovalue) {
  const auto [nx, ny, nz] = grid.dims;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j) {
      const bool full_row = k == 0 || k == nz - 1 || j == 0 || j == ny - 1;
      if (full_row) {
        for (int i = 0; i < nx; ++i)
          if (grid.at(i, j, k) >= isovalue) return true;
      } else if (grid.at(0, j, k) >= isovalue || grid.at(nx - 1, j, k) >= isovalue) {
        return true;
      }
    }
  return false;
}

Grid sample_enclosing(const Vec3& lo, const Vec3& hi, double h, int margin_cells, double isovalue,
                      double max_memory_bytes, const std::function<void(Grid&)>& fill,
                      const Reporter& reporter) {
  int margin = margin_cells;
  for (int attempt = 0;; ++attempt) {
    Grid grid = lattice_around(lo, hi, h, margin, max_memory_bytes);
    fill(grid);
    if (!reaches_boundary(grid, isovalue)) return grid;
    if (attempt == 4) {
      reporter.warn(
          "the blurred field reaches the isovalue on the grid boundary; the surface is closed "
          "along the boundary");
      return grid;
    }
    margin = 2 * margin + 4;  // overlapping tails reach farther than any lone atom
  }
}

}  // namespace molmesh
