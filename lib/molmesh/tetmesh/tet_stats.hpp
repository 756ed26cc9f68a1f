#pragma once
// Quality numbers of a tetrahedral mesh, for --stats and the tests.
#include <array>
#include <cstddef>
#include <map>

#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh {

struct TetStats {
  std::size_t vertices = 0;
  std::size_t tetrahedra = 0;
  std::size_t boundary_faces = 0;
  std::map<int, std::size_t> tets_per_region;      // region marker → count
  std::map<int, std::size_t> faces_per_marker;     // boundary marker → count
  std::map<int, std::size_t> vertices_per_marker;  // vertex marker → count
  double min_dihedral_deg = 0.0;
  double max_dihedral_deg = 0.0;
  double min_volume = 0.0;  // Å³; > 0 for a valid mesh
  double max_volume = 0.0;
  std::size_t inverted_or_flat = 0;  // tets with volume <= 0
  // Radius-edge ratio R/l_min (circumradius over shortest edge; 0.612 for a regular tet).
  double min_radius_edge = 0.0;
  double max_radius_edge = 0.0;
  double mean_radius_edge = 0.0;
  // Counts of tets with radius-edge ratio in [edges[i], edges[i+1]); the last bin is open.
  static constexpr std::array<double, 8> kRadiusEdgeBins{0.6, 0.8, 1.0, 1.25, 1.5, 2.0, 3.0, 5.0};
  std::array<std::size_t, kRadiusEdgeBins.size()> radius_edge_histogram{};
  // Dihedral angles in 10° bins [0,10), ..., [170,180].
  std::array<std::size_t, 18> dihedral_histogram{};
};

TetStats compute_tet_stats(const TetMesh& mesh);

}  // namespace molmesh
