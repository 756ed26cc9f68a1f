#pragma once
// The lattice every volume made from atoms is sampled on: Eq. 1's Gaussian (gaussian_blur),
// its fast version (fast_blur) and the distance fields (ball_union, ses_field). Its origin
// lies on integer multiples of the spacing, so translating a molecule by whole cells
// translates the samples exactly, and the grids of one molecule coincide sample by sample
// whichever field fills them. One place also decides how large a grid may be.
#include <functional>

#include "molmesh/core/geometry.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh {

// Samples at most: marching cubes numbers its vertices (up to three per sample) with
// 32-bit integers.
inline constexpr double kMaxGridSamples = 2147483647.0 / 4;

// The lattice of spacing h covering [lo, hi] plus `margin_cells` cells on every side:
// origin, spacing and dims set, no values. Throws Error, before anything is allocated, when
// the grid would need more than max_memory_bytes at bytes_per_sample (the message says how
// much it would take and to use a coarser `spacing`) or more than kMaxGridSamples samples.
Grid lattice_around(const Vec3& lo, const Vec3& hi, double h, int margin_cells,
                    double max_memory_bytes, double bytes_per_sample = sizeof(double));

// Sets every value to `fill`; a failed allocation is an Error naming the grid's size.
void allocate_values(Grid& grid, double fill);

// True when a sample on the grid's outer faces is >= isovalue: the level set would be cut
// open by the grid's boundary.
bool reaches_boundary(const Grid& grid, double isovalue);

// A field that decays away from [lo, hi] sampled so its level set `isovalue` closes inside
// the grid: `fill` sets the values of lattice_around(lo, hi, h, margin, ...), and while the
// field still reaches the isovalue on the boundary (overlapping tails reach farther than
// any lone atom), the margin grows (m -> 2m + 4) and the field is sampled again; after five
// tries the last grid is returned with a warning (the surface is then closed along the
// boundary).
Grid sample_enclosing(const Vec3& lo, const Vec3& hi, double h, int margin_cells, double isovalue,
                      double max_memory_bytes, const std::function<void(Grid&)>& fill,
                      const Reporter& reporter);

}  // namespace molmesh
