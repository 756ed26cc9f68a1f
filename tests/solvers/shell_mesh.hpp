#pragma once
// Test-only meshes with known geometry for the solver tests: a spherical shell (optionally
// with the ball inside it) built from an icosphere extruded into radial layers, each prism
// split into three tetrahedra by the minimum-vertex-index rule (conforming across shared
// faces), and the prolongation between two such meshes. Independent of the meshing
// pipeline so the FEM and multigrid can be verified on their own.
#include <Eigen/SparseCore>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh::test {

struct Icosphere {
  std::vector<Vec3> directions;             // unit vectors
  std::vector<Triangle> triangles;          // outward
  std::vector<std::array<int, 2>> parents;  // midpoint parents; {v, v} for old vertices
  std::vector<int> vertex_count_per_level;  // prefix sizes after 0, 1, ... subdivisions
};

inline Icosphere make_icosphere(int subdivisions) {
  Icosphere s;
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const double raw[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                             {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                             {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : raw) s.directions.push_back(Vec3(p[0], p[1], p[2]).normalized());
  s.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                 {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                 {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int v = 0; v < 12; ++v) s.parents.push_back({v, v});
  s.vertex_count_per_level.push_back(12);
  for (int level = 0; level < subdivisions; ++level) {
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      auto it = midpoint.find(key);
      if (it != midpoint.end()) return it->second;
      const int id = static_cast<int>(s.directions.size());
      s.directions.push_back(
          (s.directions[static_cast<std::size_t>(a)] + s.directions[static_cast<std::size_t>(b)])
              .normalized());
      s.parents.push_back({a, b});
      midpoint.emplace(key, id);
      return id;
    };
    std::vector<Triangle> next;
    for (const Triangle& tri : s.triangles) {
      const int ab = mid(tri[0], tri[1]), bc = mid(tri[1], tri[2]), ca = mid(tri[2], tri[0]);
      next.push_back({tri[0], ab, ca});
      next.push_back({tri[1], bc, ab});
      next.push_back({tri[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    s.triangles = std::move(next);
    s.vertex_count_per_level.push_back(static_cast<int>(s.directions.size()));
  }
  return s;
}

struct ShellSpec {
  double inner_radius = 10.0;
  double outer_radius = 100.0;
  int subdivisions = 3;
  int radial_layers = 8;
  bool geometric = true;  // layer radii in geometric progression (else uniform)
  int ball_layers = 0;    // > 0: also mesh the ball inside (region 1), centre is vertex 0
};

struct ShellMesh {
  ShellSpec spec;
  TetMesh mesh;
  std::vector<double> radii;  // per layer (ball layers first); centre not included
  int surface_vertices = 0;
  bool has_centre = false;
};

inline ShellMesh make_shell_mesh(const ShellSpec& spec) {
  ShellMesh out;
  out.spec = spec;
  const Icosphere sphere = make_icosphere(spec.subdivisions);
  const int ns = static_cast<int>(sphere.directions.size());
  out.surface_vertices = ns;
  out.has_centre = spec.ball_layers > 0;
  for (int k = 1; k < spec.ball_layers; ++k) {
    out.radii.push_back(spec.inner_radius * k / spec.ball_layers);
  }
  for (int k = 0; k <= spec.radial_layers; ++k) {
    const double f = static_cast<double>(k) / spec.radial_layers;
    out.radii.push_back(spec.geometric
                            ? spec.inner_radius * std::pow(spec.outer_radius / spec.inner_radius, f)
                            : spec.inner_radius + f * (spec.outer_radius - spec.inner_radius));
  }
  const int offset = out.has_centre ? 1 : 0;
  TetMesh& m = out.mesh;
  if (out.has_centre) m.points.push_back(Vec3::Zero());
  for (double r : out.radii) {
    for (const Vec3& d : sphere.directions) m.points.push_back(r * d);
  }
  auto id = [&](int layer, int v) { return offset + layer * ns + v; };
  const double surface_radius = spec.inner_radius * (1.0 + 1e-12);
  auto add = [&](Tetrahedron tet, double outer_r) {
    const Vec3& p0 = m.points[static_cast<std::size_t>(tet[0])];
    const double det = (m.points[static_cast<std::size_t>(tet[1])] - p0)
                           .dot((m.points[static_cast<std::size_t>(tet[2])] - p0)
                                    .cross(m.points[static_cast<std::size_t>(tet[3])] - p0));
    if (det < 0) std::swap(tet[2], tet[3]);
    m.tetrahedra.push_back(tet);
    m.cell_markers.push_back(outer_r <= surface_radius ? markers::kMoleculeRegion
                                                       : markers::kSolventRegion);
  };
  const int layers = static_cast<int>(out.radii.size());
  if (out.has_centre) {
    for (const Triangle& t : sphere.triangles)
      add({0, id(0, t[0]), id(0, t[1]), id(0, t[2])}, out.radii[0]);
  }
  for (int k = 0; k + 1 < layers; ++k) {
    for (const Triangle& t : sphere.triangles) {
      // Rotate so the bottom vertex with the smallest index comes first (the prism's
      // minimum, since top ids are bottom ids + ns).
      int r = 0;
      if (t[1] < t[r]) r = 1;
      if (t[2] < t[r]) r = 2;
      const int a = t[static_cast<std::size_t>(r)], b = t[static_cast<std::size_t>((r + 1) % 3)],
                c = t[static_cast<std::size_t>((r + 2) % 3)];
      const int v0 = id(k, a), v1 = id(k, b), v2 = id(k, c);
      const int v3 = id(k + 1, a), v4 = id(k + 1, b), v5 = id(k + 1, c);
      const double ro = out.radii[static_cast<std::size_t>(k + 1)];
      if (std::min(v1, v5) < std::min(v2, v4)) {
        add({v0, v1, v2, v5}, ro);
        add({v0, v1, v5, v4}, ro);
        add({v0, v4, v5, v3}, ro);
      } else {
        add({v0, v1, v2, v4}, ro);
        add({v0, v4, v2, v5}, ro);
        add({v0, v4, v5, v3}, ro);
      }
    }
  }
  m.vertex_markers.assign(m.points.size(), markers::kNoMarker);
  const int surface_layer = out.has_centre ? spec.ball_layers - 1 : 0;
  for (const Triangle& t : sphere.triangles) {
    m.boundary_faces.push_back(
        {id(surface_layer, t[0]), id(surface_layer, t[2]), id(surface_layer, t[1])});
    m.boundary_face_markers.push_back(markers::kMolecularSurface);
    m.boundary_faces.push_back({id(layers - 1, t[0]), id(layers - 1, t[1]), id(layers - 1, t[2])});
    m.boundary_face_markers.push_back(markers::kOuterSphere);
  }
  for (std::size_t f = 0; f < m.boundary_faces.size(); ++f) {
    for (int v : m.boundary_faces[f]) {
      m.vertex_markers[static_cast<std::size_t>(v)] = m.boundary_face_markers[f];
    }
  }
  return out;
}

// Prolongation coarse -> fine: linear in the radius between the coarse layers (and the
// centre), and on the sphere either the identity or the midpoint rule of one subdivision.
inline SparseMatrix shell_prolongation(const ShellMesh& coarse, const ShellMesh& fine) {
  const int sc = coarse.spec.subdivisions, sf = fine.spec.subdivisions;
  const Icosphere sphere = make_icosphere(sf);
  const int nsc = coarse.surface_vertices, nsf = fine.surface_vertices;
  // Coarse radii with the centre (radius 0) first when present.
  std::vector<double> cr;
  std::vector<int> clayer;  // -1 = centre
  if (coarse.has_centre) {
    cr.push_back(0.0);
    clayer.push_back(-1);
  }
  for (std::size_t k = 0; k < coarse.radii.size(); ++k) {
    cr.push_back(coarse.radii[k]);
    clayer.push_back(static_cast<int>(k));
  }
  const int coff = coarse.has_centre ? 1 : 0, foff = fine.has_centre ? 1 : 0;
  auto coarse_id = [&](int layer, int v) { return layer < 0 ? 0 : coff + layer * nsc + v; };
  std::vector<Eigen::Triplet<double, int>> triplets;
  auto angular = [&](int v, std::vector<std::pair<int, double>>& w) {
    w.clear();
    if (sf == sc || v < nsc) {
      w.push_back({v, 1.0});
    } else {
      w.push_back({sphere.parents[static_cast<std::size_t>(v)][0], 0.5});
      w.push_back({sphere.parents[static_cast<std::size_t>(v)][1], 0.5});
    }
  };
  if (fine.has_centre) triplets.emplace_back(0, 0, 1.0);
  std::vector<std::pair<int, double>> aw;
  for (std::size_t k = 0; k < fine.radii.size(); ++k) {
    const double r = fine.radii[k];
    std::size_t j = 0;
    while (j + 2 < cr.size() && cr[j + 1] < r * (1 - 1e-12)) ++j;
    const double t = std::clamp((r - cr[j]) / (cr[j + 1] - cr[j]), 0.0, 1.0);
    for (int v = 0; v < nsf; ++v) {
      const int row = foff + static_cast<int>(k) * nsf + v;
      angular(v, aw);
      for (const auto& [cv, w] : aw) {
        if (1.0 - t > 1e-14) triplets.emplace_back(row, coarse_id(clayer[j], cv), (1.0 - t) * w);
        if (t > 1e-14) triplets.emplace_back(row, coarse_id(clayer[j + 1], cv), t * w);
      }
    }
  }
  SparseMatrix p(static_cast<Eigen::Index>(fine.mesh.points.size()),
                 static_cast<Eigen::Index>(coarse.mesh.points.size()));
  p.setFromTriplets(triplets.begin(), triplets.end());
  return p;
}

// A family of `levels` meshes, each refining the previous once on the sphere and twice
// radially; returns the finest mesh and the prolongations finest-first, as in Hierarchy.
struct ShellHierarchy {
  std::vector<ShellMesh> meshes;            // [0] finest
  std::vector<SparseMatrix> prolongations;  // [l]: level l+1 -> level l
};

inline ShellHierarchy make_shell_hierarchy(ShellSpec finest, int levels) {
  ShellHierarchy h;
  ShellSpec spec = finest;
  for (int l = 0; l < levels; ++l) {
    h.meshes.push_back(make_shell_mesh(spec));
    spec.subdivisions = std::max(0, spec.subdivisions - 1);
    spec.radial_layers = std::max(1, spec.radial_layers / 2);
    if (spec.ball_layers > 0) spec.ball_layers = std::max(1, spec.ball_layers / 2);
  }
  for (int l = 0; l + 1 < levels; ++l) {
    h.prolongations.push_back(shell_prolongation(h.meshes[static_cast<std::size_t>(l + 1)],
                                                 h.meshes[static_cast<std::size_t>(l)]));
  }
  return h;
}

}  // namespace molmesh::test
