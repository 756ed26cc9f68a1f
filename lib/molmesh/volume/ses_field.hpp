#pragma once
// The solvent-excluded surface (SES, Connolly's molecular surface) as a distance-like field:
// with E the set of admissible probe centres (outside every ball of radius r_i + p, i.e.
// outside the SAS), the solvent reaches the points within p of E, so
//   S(x) = dist(x, E) - p
// is positive inside the SES, zero on it and -p outside the SAS. dist(x, E) is the exact
// Euclidean distance transform of the grid samples in E (distance_transform.hpp); near the
// surface (where |S| is within a few cells of 0) it is replaced by the exact distance from x
// to the SAS boundary, found among the sphere, circle and vertex points of the atoms whose
// SAS sphere passes by the nearest E sample (docs/surface.md), so the surface is placed to
// within marching cubes' interpolation error, not to within a voxel.
#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/core/resource_limits.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh {

// Throws Error for a non-positive spacing, a negative probe radius, no atom with a
// positive radius, or a grid whose field and distance transform would need more than
// max_memory_bytes (said before allocating). probe = 0 gives the vdW field.
// Deterministic and independent of the thread count.
Grid ses_field(const Atoms& atoms, double probe, double spacing, const Reporter& reporter = {},
               double max_memory_bytes = default_memory_limit());

}  // namespace molmesh
