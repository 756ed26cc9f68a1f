#pragma once
// Tetrahedral meshing of a molecular surface with TetGen (GAMer §2.4): the molecule's
// interior (every atom centre a mesh node), the solvent between the surface and a large
// outer sphere, or both in one conforming mesh. The molecular surface is kept exactly as
// given (no Steiner points on it), so the surface pipeline's quality carries over.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/core/geometry.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/core/resource_limits.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/size_field.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh {

enum class Domain { interior, exterior, full };

// Every domain, for the front ends that spell them (CLI --domain, Python domain=).
inline constexpr std::array<Domain, 3> kDomains{Domain::interior, Domain::exterior, Domain::full};

// "interior", "exterior", "full": the spelling of --domain and of hierarchy files.
std::string domain_name(Domain domain);

// Largest outer sphere radius (Å): far enough for any molecule's far field (the default is
// 40 x the molecule size); beyond, TetGen's predicates lose the molecule against the sphere
// (--outer-radius 1e300 aborted in a TetGen assertion).
inline constexpr double kMaxOuterRadius = 1e6;

// The other ranges TetMeshOptions::validate() accepts (docs/tetmesh.md, "Limits"), for the
// front ends that check values while parsing (the CLI's volume options) with the same bounds.
inline constexpr double kMaxSphereRatio = 1e4;         // sphere_ratio in (0, this]
inline constexpr int kMaxOuterSphereSubdivisions = 7;  // outer_sphere_subdivisions 0..this
inline constexpr double kMinRadiusEdgeRatio = 1.0;     // TetGen may not terminate below 1
inline constexpr double kMaxRadiusEdgeRatio = 1e3;     // max_radius_edge_ratio upper bound
inline constexpr double kMaxMinDihedralDeg = 70.0;     // min_dihedral_deg in [0, this]
inline constexpr double kMaxSizeFactor = 1e3;          // size_factor in [0, this]
inline constexpr double kMaxSurfaceSizeRatio = 100.0;  // surface_size_ratio in (0, this]

struct TetMeshOptions {
  Domain domain = Domain::full;
  // Outer sphere radius = sphere_ratio × molecule size (max distance of atom centres from
  // their mean; of surface points when there are no atoms). 40 as in the paper.
  double sphere_ratio = 40.0;
  std::optional<double> outer_radius;  // Å; overrides sphere_ratio
  // Outer-sphere triangulation: icosphere subdivision level (level L has 10·4^L + 2
  // vertices). Its triangles are large (∝ radius), so the far field stays coarse.
  int outer_sphere_subdivisions = 3;
  // Molecular-surface faces whose three vertices lie inside the union get kActiveSite.
  std::vector<Sphere> active_site;
  // TetGen -q bounds: the radius-edge ratio bound drives Delaunay refinement (and the
  // outward grading); the dihedral bound is enforced by TetGen's optimisation.
  double max_radius_edge_ratio = 2.0;
  double min_dihedral_deg = 10.0;
  std::optional<double> max_volume;  // Å³, TetGen -a (uniform upper bound)
  // Size field (TetGen -m, tetmesh/size_field.hpp) × size_factor: 1.5 × the mean edge
  // length at each molecular-surface vertex, h = 0.09 R (r/R)^1.2 through the solvent of
  // exterior and full meshes (a background mesh), the grading that equidistributes the P1
  // energy error of a 1/r field. 0 switches grading off: then only the radius-edge bound
  // grades the mesh, which leaves the tetrahedra next to the surface several times larger.
  double size_factor = 1.0;
  // The size at a molecular-surface vertex, in mean edge lengths of its star (before
  // size_factor). 1.5 (size_field.hpp) serves rates and the Born ion; a protein's solvation
  // energy with point charges needs the dielectric boundary finer: 0.6 put 1a1p's SES within
  // 4 % of APBS at a fifth of the unknowns `size_factor` 0.4 needs (docs/surface.md).
  double surface_size_ratio = kSurfaceSizeRatio;
  // Expert override: replaces every switch molmesh would choose (besides Q, which is
  // always added so TetGen stays silent). Must keep the meaning of the result a PLC mesh
  // with region attributes, e.g. "pq1.5/15YA".
  std::string tetgen_switches;
  // Memory TetGen may use, in bytes: a request whose estimated mesh (about 400 bytes per
  // tetrahedron) needs more is refused before TetGen runs (core/resource_limits.hpp).
  double max_memory_bytes = default_memory_limit();

  // Throws Error naming the option when a value is NaN, infinite or outside the range
  // molmesh supports (docs/tetmesh.md, "Limits"); tetrahedralize() calls it first.
  void validate() const;
};

struct TetMeshReport {
  std::size_t atoms_given = 0;             // atoms passed in
  std::size_t atoms_as_nodes = 0;          // distinct atom centres that are mesh vertices
  std::size_t coincident_atoms = 0;        // atoms whose centre duplicates an earlier one
  std::size_t atoms_outside = 0;           // centres outside the meshed interior (not nodes)
  std::size_t surface_vertices = 0;        // molecular-surface vertices given
  std::size_t surface_steiner_points = 0;  // vertices TetGen added on the surface (0 with Y)
  std::size_t outer_sphere_vertices = 0;
  double molecule_size = 0.0;   // Å
  double outer_radius = 0.0;    // Å (0 for an interior mesh)
  std::string tetgen_switches;  // the switches TetGen ran with
  double seconds = 0.0;         // TetGen wall time
  double total_seconds = 0.0;   // including input preparation and classification
};

// Throws molmesh::Error when the surface is empty or not closed enough for TetGen, when the
// outer sphere would not enclose the surface, or when TetGen fails (its error code is
// translated into a message). `atoms` may be empty (surface-file inputs).
TetMesh tetrahedralize(const SurfaceMesh& molecular_surface, const Atoms& atoms,
                       const TetMeshOptions& options, const Reporter& reporter = {},
                       TetMeshReport* report = nullptr);

}  // namespace molmesh
