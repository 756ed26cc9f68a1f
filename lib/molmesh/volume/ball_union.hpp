#pragma once
// The van der Waals and solvent-accessible volumes: the union of balls of radius
// r_i + grow (grow = 0 for vdW, the probe radius for the SAS) sampled as
//   U(x) = max_i (r_i + grow - |x - c_i|),
// positive inside, zero exactly on the union's boundary, and equal to minus the distance to
// the union outside it. U is computed exactly within two cells of every ball (so every
// sample next to a crossing of level 0 is exact, and marching cubes' linear interpolation
// places vertices to within h^2 / (8 r) of the spheres); farther out it is clamped to minus
// two cells. Atoms with zero radius add nothing, as in Eq. 1.
#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/core/resource_limits.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh {

// An empty grid (origin, spacing, dims; no values) that holds every ball of radius
// r_i + grow plus `margin_cells` cells, on the atoms' lattice (grid_lattice.hpp). Throws
// Error for a non-positive spacing, a negative grow, no atom with a positive radius, or a
// grid that would need more than max_memory_bytes at bytes_per_sample (what the field
// built on it needs per sample).
Grid ball_union_grid(const Atoms& atoms, double grow, double spacing, int margin_cells,
                     double max_memory_bytes = default_memory_limit(),
                     double bytes_per_sample = sizeof(double));

// Fills grid.values with U (the grid's origin, spacing and dims are kept). Deterministic:
// a maximum does not depend on the order the atoms are visited in.
void ball_union_onto(const Atoms& atoms, double grow, Grid& grid, const Reporter& reporter = {});

// ball_union_grid + ball_union_onto with 3 margin cells.
Grid ball_union_field(const Atoms& atoms, double grow, double spacing,
                      const Reporter& reporter = {},
                      double max_memory_bytes = default_memory_limit());

}  // namespace molmesh
