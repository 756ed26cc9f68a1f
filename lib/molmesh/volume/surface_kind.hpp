#pragma once
// Which molecular surface the volume describes (docs/surface.md has the definitions):
//   kGaussian  the paper's Eq. 1 blurred density, contoured at an isovalue;
//   kVdw       the union of the atoms' van der Waals balls;
//   kSas       the solvent-accessible surface: balls grown by the probe radius;
//   kSes       the solvent-excluded (molecular) surface: what a probe ball rolling over the
//              atoms cannot reach.
// The three geometric kinds are sampled as distance-like fields that are positive inside,
// negative outside and zero on the surface (docs/surface.md), so marching cubes contours
// them at level 0 with the same inside test (value >= level) as the Gaussian.
#include <array>
#include <string>

namespace molmesh {

enum class SurfaceKind { kGaussian, kVdw, kSas, kSes };

// Every kind, for the front ends that spell them (CLI --surface, Python surface=).
inline constexpr std::array<SurfaceKind, 4> kSurfaceKinds{SurfaceKind::kGaussian, SurfaceKind::kVdw,
                                                          SurfaceKind::kSas, SurfaceKind::kSes};

// "gaussian", "vdw", "sas", "ses": the spelling of --surface, stats JSON and hierarchy files.
std::string surface_kind_name(SurfaceKind kind);

}  // namespace molmesh
