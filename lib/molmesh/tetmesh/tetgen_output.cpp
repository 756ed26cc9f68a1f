#include "molmesh/tetmesh/tetgen_output.hpp"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/geometry/predicates.hpp"
#include "molmesh/geometry/tetrahedron.hpp"
#include "molmesh/geometry/winding_number.hpp"
#include "molmesh/tetmesh/markers.hpp"

namespace molmesh::detail {
namespace {

struct FaceKey {
  int a, b, c;  // sorted
  bool operator==(const FaceKey&) const = default;
};
FaceKey face_key(int a, int b, int c) {
  if (a > b) std::swap(a, b);
  if (b > c) std::swap(b, c);
  if (a > b) std::swap(a, b);
  return {a, b, c};
}
struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::uint64_t h = static_cast<std::uint32_t>(k.a);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.b);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k.c);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

using FacetMarkers = std::unordered_map<FaceKey, int, FaceKeyHash>;

Vec3 tetgen_point(const tetgenio& out, int i) {
  return Vec3(out.pointlist[3 * i], out.pointlist[3 * i + 1], out.pointlist[3 * i + 2]);
}

// The face opposite corner k, ordered so the normal points out of the tet.
Triangle face_opposite(const Tetrahedron& t, int k) {
  return Triangle{t[kTetFaces[k][0]], t[kTetFaces[k][1]], t[kTetFaces[k][2]]};
}

// Regions: tets connected across faces that are not on an input facet. Each is classified
// by the winding number of the molecular surface at one tet's centroid, so cavities
// (inside the surface but outside the molecule) come out as solvent.
struct Regions {
  std::vector<int> component;         // per tet
  std::vector<int> component_region;  // per component: markers::kMoleculeRegion or kSolventRegion
};
Regions classify_regions(const std::vector<Tetrahedron>& tets,
                         const std::vector<std::array<int, 4>>& nbr,
                         const FacetMarkers& facet_marker, const tetgenio& out,
                         const SurfaceMesh& surface) {
  const int n_tets = static_cast<int>(tets.size());
  auto point_at = [&](int i) { return tetgen_point(out, i); };
  std::vector<int> component(static_cast<std::size_t>(n_tets), -1);
  std::vector<int> component_region;
  std::vector<int> stack;
  for (int seed = 0; seed < n_tets; ++seed) {
    if (component[seed] >= 0) continue;
    const int id = static_cast<int>(component_region.size());
    component[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int t = stack.back();
      stack.pop_back();
      for (int k = 0; k < 4; ++k) {
        const int n = nbr[t][k];
        if (n < 0 || component[n] >= 0) continue;
        const Triangle f = face_opposite(tets[t], k);
        if (facet_marker.count(face_key(f[0], f[1], f[2]))) continue;
        component[n] = id;
        stack.push_back(n);
      }
    }
    const Tetrahedron& st = tets[seed];
    const Vec3 centroid =
        (point_at(st[0]) + point_at(st[1]) + point_at(st[2]) + point_at(st[3])) / 4.0;
    component_region.push_back(winding_number(surface.points, surface.triangles, centroid) > 0.5
                                   ? markers::kMoleculeRegion
                                   : markers::kSolventRegion);
  }
  return {std::move(component), std::move(component_region)};
}

// Vertex markers: the highest-ranked marker of the faces around (markers.hpp).
void assign_vertex_markers(TetMesh& mesh) {
  mesh.vertex_markers.assign(mesh.points.size(), markers::kNoMarker);
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const int m = mesh.boundary_face_markers[f];
    for (int v : mesh.boundary_faces[f])
      if (markers::vertex_marker_rank(m) > markers::vertex_marker_rank(mesh.vertex_markers[v]))
        mesh.vertex_markers[v] = m;
  }
}

}  // namespace

TetMesh mesh_from_tetgen(const tetgenio& out, const SurfaceMesh& surface,
                         const TetGenOutputOptions& options, std::size_t* surface_steiner_points) {
  const int n_out_points = out.numberofpoints;
  const int n_tets = out.numberoftetrahedra;
  if (n_tets <= 0 || out.tetrahedronlist == nullptr || out.neighborlist == nullptr)
    throw Error("TetGen produced no tetrahedra");

  // Faces TetGen kept on the input facets, with their markers: they separate regions.
  FacetMarkers facet_marker;
  facet_marker.reserve(static_cast<std::size_t>(out.numberoftrifaces) * 2);
  for (int f = 0; f < out.numberoftrifaces; ++f) {
    const int* v = out.trifacelist + 3 * f;
    facet_marker[face_key(v[0], v[1], v[2])] =
        out.trifacemarkerlist ? out.trifacemarkerlist[f] : markers::kMolecularSurface;
  }

  // Tets as given by TetGen, reoriented positively; neighbour k stays opposite corner k.
  std::vector<Tetrahedron> tets(static_cast<std::size_t>(n_tets));
  std::vector<std::array<int, 4>> nbr(static_cast<std::size_t>(n_tets));
  auto point_at = [&](int i) { return tetgen_point(out, i); };
  for (int t = 0; t < n_tets; ++t) {
    Tetrahedron tet{out.tetrahedronlist[4 * t], out.tetrahedronlist[4 * t + 1],
                    out.tetrahedronlist[4 * t + 2], out.tetrahedronlist[4 * t + 3]};
    std::array<int, 4> nb{out.neighborlist[4 * t], out.neighborlist[4 * t + 1],
                          out.neighborlist[4 * t + 2], out.neighborlist[4 * t + 3]};
    if (orient3d(point_at(tet[0]), point_at(tet[1]), point_at(tet[2]), point_at(tet[3])) < 0.0) {
      std::swap(tet[2], tet[3]);
      std::swap(nb[2], nb[3]);
    }
    tets[t] = tet;
    nbr[t] = nb;
  }

  const Regions regions = classify_regions(tets, nbr, facet_marker, out, surface);
  const std::vector<int>& component = regions.component;
  const std::vector<int>& component_region = regions.component_region;

  auto keep_region = [&](int region) {
    return region == markers::kMoleculeRegion ? options.keep_molecule : options.keep_solvent;
  };

  // Compact: kept tets and the points they use, in TetGen's order.
  TetMesh mesh;
  std::vector<int> new_point(static_cast<std::size_t>(n_out_points), -1);
  std::vector<int> new_tet(static_cast<std::size_t>(n_tets), -1);
  for (int t = 0; t < n_tets; ++t) {
    if (!keep_region(component_region[component[t]])) continue;
    for (int v : tets[t]) new_point[v] = 0;
  }
  for (int i = 0; i < n_out_points; ++i) {
    if (new_point[i] < 0) continue;
    new_point[i] = static_cast<int>(mesh.points.size());
    mesh.points.push_back(point_at(i));
  }
  for (int t = 0; t < n_tets; ++t) {
    const int region = component_region[component[t]];
    if (!keep_region(region)) continue;
    new_tet[t] = static_cast<int>(mesh.tetrahedra.size());
    const Tetrahedron& tet = tets[t];
    mesh.tetrahedra.push_back(
        {new_point[tet[0]], new_point[tet[1]], new_point[tet[2]], new_point[tet[3]]});
    mesh.cell_markers.push_back(region);
  }
  if (mesh.tetrahedra.empty())
    throw Error("no tetrahedra lie in the requested domain (is the surface oriented outward?)");

  // Boundary faces of the kept set, and (full meshes) the molecule/solvent interface once,
  // oriented out of the molecule.
  for (int t = 0; t < n_tets; ++t) {
    if (new_tet[t] < 0) continue;
    const int region = component_region[component[t]];
    for (int k = 0; k < 4; ++k) {
      const int n = nbr[t][k];
      const bool boundary = n < 0 || new_tet[n] < 0;
      const bool interface = !boundary && region == markers::kMoleculeRegion &&
                             component_region[component[n]] != region;
      if (!boundary && !interface) continue;
      const Triangle f = face_opposite(tets[t], k);
      const auto it = facet_marker.find(face_key(f[0], f[1], f[2]));
      mesh.boundary_faces.push_back({new_point[f[0]], new_point[f[1]], new_point[f[2]]});
      mesh.boundary_face_markers.push_back(it == facet_marker.end() ? markers::kNoMarker
                                                                    : it->second);
    }
  }

  assign_vertex_markers(mesh);

  std::size_t steiner = 0;
  // Vertices on the molecular surface that were not given: Steiner points (0 with Y).
  for (int i = options.input_points; i < n_out_points; ++i) {
    const int v = new_point[i];
    if (v >= 0 && (mesh.vertex_markers[v] == markers::kMolecularSurface ||
                   mesh.vertex_markers[v] == markers::kActiveSite))
      ++steiner;
  }
  if (surface_steiner_points) *surface_steiner_points = steiner;
  return mesh;
}

}  // namespace molmesh::detail
