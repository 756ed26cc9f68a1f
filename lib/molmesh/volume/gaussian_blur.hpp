#pragma once
// Eq. 1 of the GAMer paper: F(x) = sum_i exp(B_i (|x - c_i|^2 / r_i^2 - 1)), sampled on a
// regular grid that encloses the isosurface F = isovalue with a margin. F is large inside
// the molecule and decreases outward. Decisions (cutoff, error bound, margin) are in
// docs/surface.md.
#include <array>
#include <cstddef>
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/core/resource_limits.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh {

struct BlurOptions {
  double spacing = 0.5;      // Å, same along x, y, z
  double blobbyness = -0.5;  // global B (< 0), used when Atom::blobbyness is unset
  double isovalue = 1.0;     // the level the surface will be extracted at; sizes the margin
  // Each atom's kernel is cut off where it falls below truncation * isovalue, i.e. at
  // distance r * sqrt(1 + ln(truncation * isovalue) / B). Beyond that it adds nothing.
  double truncation = 1e-4;
  // Whole grid cells added beyond the farthest point where any lone atom reaches the
  // isovalue. The grid is enlarged automatically if the blurred field still reaches the
  // isovalue on its boundary (many overlapping tails), so the surface is always closed.
  int margin_cells = 3;
  // Bytes the grid may take (8 per sample); a larger grid is refused before it is
  // allocated, with the size it would need (core/resource_limits.hpp).
  double max_memory_bytes = default_memory_limit();
};

// Throws Error for a non-positive spacing or isovalue, a truncation outside (0, 1) or a
// negative margin (the checks blur_atoms and GaussianField share).
void check_blur_options(const BlurOptions& options);

// An atom Eq. 1 sums: one with a positive radius, with its B_i (Atom::blobbyness, or the
// global B). `index` is its position in the input.
struct BlurredAtom {
  Vec3 center;
  double radius = 0.0;
  double blobbyness = 0.0;
  std::size_t index = 0;
};

// The atoms with a positive radius, in input order. Throws Error for a non-negative or
// non-finite B_i, a non-finite position, or no atom with a positive radius.
std::vector<BlurredAtom> blurred_atoms(const Atoms& atoms, double blobbyness);

// Atoms with zero radius add nothing. Throws Error for non-negative blobbyness, a
// non-positive spacing/isovalue/truncation, no atom with a positive radius, or a grid too
// large to allocate (the message gives its size). Deterministic: the sum at each grid point
// runs over atoms in input order whatever the number of threads.
Grid blur_atoms(const Atoms& atoms, const BlurOptions& options, const Reporter& reporter = {});

// The distance from an atom's centre at which its kernel equals `value` (> 0), or 0 when
// it never reaches it. Exposed for the margin logic and for tests.
double kernel_radius(double radius, double blobbyness, double value);

}  // namespace molmesh
