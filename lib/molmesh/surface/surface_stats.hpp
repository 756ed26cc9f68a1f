#pragma once
// Quality and topology metrics of a triangle surface (the --stats JSON, `molmesh stats`).
#include <array>
#include <cstddef>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct SurfaceStats {
  std::size_t vertices = 0;  // points referenced by at least one triangle
  std::size_t triangles = 0;
  double min_angle_deg = 0.0;
  double max_angle_deg = 0.0;
  std::array<double, 18> angle_histogram_percent{};  // bins of 10°: [0,10), ..., [170,180]
  double fraction_angles_40_80 = 0.0;                // in [0, 1], of all triangle angles
  double area = 0.0;                                 // Å²
  double volume = 0.0;            // signed enclosed volume (Å³), > 0 for outward normals
  int components = 0;             // connected through shared vertices
  long euler_characteristic = 0;  // V - E + F over referenced vertices
  bool closed = false;            // every edge has exactly two triangles
  // Every edge has one or two triangles, two only with opposite orientations, and the
  // triangles around every vertex form a single fan.
  bool manifold = false;
};

SurfaceStats compute_surface_stats(const SurfaceMesh& mesh);

}  // namespace molmesh
