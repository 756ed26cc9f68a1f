#include "molmesh/io/gmsh.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <map>
#include <ostream>
#include <set>
#include <string>

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/text_output.hpp"
#include "molmesh/tetmesh/markers.hpp"

namespace molmesh {
namespace {

constexpr int kGmshTriangle = 2;
constexpr int kGmshTetra = 4;

std::string region_name(int region) {
  switch (region) {
    case markers::kMoleculeRegion:
      return "molecule";
    case markers::kSolventRegion:
      return "solvent";
    default:
      return "region_" + std::to_string(region);
  }
}

std::string face_name(int marker) {
  switch (marker) {
    case markers::kMolecularSurface:
      return "molecular_surface";
    case markers::kOuterSphere:
      return "outer_sphere";
    case markers::kActiveSite:
      return "active_site";
    default:
      return "boundary_" + std::to_string(marker);
  }
}

// Gmsh physical tags must be positive; unmarked cells and faces go to tag 0 → 100 + 0.
int physical_tag(int marker) { return marker > 0 ? marker : 100 - marker; }

using io_detail::TextOutput;

int cell_marker(const TetMesh& mesh, std::size_t t) {
  return t < mesh.cell_markers.size() ? mesh.cell_markers[t] : 0;
}

// Faces and tetrahedra grouped by physical tag (std::map: ascending, deterministic).
struct Groups {
  std::map<int, std::vector<std::size_t>> faces, tets;
};

Groups group_by_tag(const TetMesh& mesh) {
  Groups g;
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    g.faces[physical_tag(mesh.boundary_face_markers[f])].push_back(f);
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    g.tets[physical_tag(cell_marker(mesh, t))].push_back(t);
  return g;
}

void write_point(TextOutput& out, const Vec3& p) {
  out.general(p.x(), 12).ch(' ').general(p.y(), 12).ch(' ').general(p.z(), 12);
}

void write_header_and_names(TextOutput& out, const TetMesh& mesh, const Groups& g,
                            GmshVersion version) {
  out.text("$MeshFormat\n")
      .text(version == GmshVersion::v2_2 ? "2.2" : "4.1")
      .text(" 0 8\n$EndMeshFormat\n$PhysicalNames\n")
      .integer(g.faces.size() + g.tets.size())
      .ch('\n');
  for (const auto& [tag, list] : g.faces)
    out.text("2 ")
        .integer(tag)
        .text(" \"")
        .text(face_name(mesh.boundary_face_markers[list.front()]))
        .text("\"\n");
  for (const auto& [tag, list] : g.tets)
    out.text("3 ")
        .integer(tag)
        .text(" \"")
        .text(region_name(cell_marker(mesh, list.front())))
        .text("\"\n");
  out.text("$EndPhysicalNames\n");
}

// MSH 2.2: nodes, then every element with its physical and elementary tag.
void write_v22_body(TextOutput& out, const TetMesh& mesh, const Groups& g) {
  const std::size_t n_elements = mesh.boundary_faces.size() + mesh.tetrahedra.size();
  out.text("$Nodes\n").integer(mesh.points.size()).ch('\n');
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    out.integer(i + 1).ch(' ');
    write_point(out, mesh.points[i]);
    out.ch('\n');
  }
  out.text("$EndNodes\n$Elements\n").integer(n_elements).ch('\n');
  std::size_t id = 1;
  auto element = [&](int type, int tag, auto vertices) {
    out.integer(id++).ch(' ').integer(type).text(" 2 ").integer(tag).ch(' ').integer(tag);
    for (int v : vertices) out.ch(' ').integer(v + 1);
    out.ch('\n');
  };
  for (const auto& [tag, list] : g.faces)
    for (std::size_t f : list) element(kGmshTriangle, tag, mesh.boundary_faces[f]);
  for (const auto& [tag, list] : g.tets)
    for (std::size_t t : list) element(kGmshTetra, tag, mesh.tetrahedra[t]);
  out.text("$EndElements\n");
}

// MSH 4.1 entities: one geometric entity per physical group (entity tag = physical tag),
// each with a bounding box.
void write_v41_entities(TextOutput& out, const TetMesh& mesh, const Groups& g) {
  auto bbox = [&](auto&& for_each_vertex) {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -lo;
    for_each_vertex([&](int v) {
      lo = lo.cwiseMin(mesh.points[v]);
      hi = hi.cwiseMax(mesh.points[v]);
    });
    write_point(out, lo);
    out.ch(' ');
    write_point(out, hi);
  };
  out.text("$Entities\n0 0 ").integer(g.faces.size()).ch(' ').integer(g.tets.size()).ch('\n');
  // clang 14 cannot capture structured bindings in a lambda (P1091 came in clang 16).
  for (const auto& entry : g.faces) {
    const int tag = entry.first;
    out.integer(tag).ch(' ');
    bbox([&, &list = entry.second](auto&& visit) {
      for (std::size_t f : list)
        for (int v : mesh.boundary_faces[f]) visit(v);
    });
    out.text(" 1 ").integer(tag).text(" 0\n");
  }
  for (const auto& entry : g.tets) {
    const int tag = entry.first;
    out.integer(tag).ch(' ');
    bbox([&, &list = entry.second](auto&& visit) {
      for (std::size_t t : list)
        for (int v : mesh.tetrahedra[t]) visit(v);
    });
    out.text(" 1 ").integer(tag).ch(' ').integer(g.faces.size());
    for (const auto& face_entry : g.faces) out.ch(' ').integer(face_entry.first);
    out.ch('\n');
  }
  out.text("$EndEntities\n");
}

// MSH 4.1 nodes (one block on the first volume entity, or surface entity) and elements (one
// block per group).
void write_v41_nodes_and_elements(TextOutput& out, const TetMesh& mesh, const Groups& g) {
  const std::size_t n_elements = mesh.boundary_faces.size() + mesh.tetrahedra.size();
  const int node_dim = g.tets.empty() ? 2 : 3;
  const int node_entity =
      g.tets.empty() ? (g.faces.empty() ? 1 : g.faces.begin()->first) : g.tets.begin()->first;
  const std::size_t n = mesh.points.size();
  out.text("$Nodes\n1 ").integer(n).text(" 1 ").integer(n).ch('\n');
  out.integer(node_dim).ch(' ').integer(node_entity).text(" 0 ").integer(n).ch('\n');
  for (std::size_t i = 0; i < n; ++i) out.integer(i + 1).ch('\n');
  for (const auto& p : mesh.points) {
    write_point(out, p);
    out.ch('\n');
  }
  out.text("$EndNodes\n$Elements\n")
      .integer(g.faces.size() + g.tets.size())
      .ch(' ')
      .integer(n_elements)
      .text(" 1 ")
      .integer(n_elements)
      .ch('\n');
  std::size_t id = 1;
  auto block = [&](int dim, int tag, int type, std::size_t size) {
    out.integer(dim).ch(' ').integer(tag).ch(' ').integer(type).ch(' ').integer(size).ch('\n');
  };
  auto element = [&](auto vertices) {
    out.integer(id++);
    for (int v : vertices) out.ch(' ').integer(v + 1);
    out.ch('\n');
  };
  for (const auto& [tag, list] : g.faces) {
    block(2, tag, kGmshTriangle, list.size());
    for (std::size_t f : list) element(mesh.boundary_faces[f]);
  }
  for (const auto& [tag, list] : g.tets) {
    block(3, tag, kGmshTetra, list.size());
    for (std::size_t t : list) element(mesh.tetrahedra[t]);
  }
  out.text("$EndElements\n");
}

}  // namespace

void write_gmsh(const std::filesystem::path& path, const TetMesh& mesh, GmshVersion version) {
  if (mesh.boundary_face_markers.size() != mesh.boundary_faces.size())
    throw Error("write_gmsh: boundary face markers do not match the faces");
  const Groups groups = group_by_tag(mesh);
  write_file_atomically(path, [&](std::ostream& stream) {
    TextOutput out(stream);
    write_header_and_names(out, mesh, groups, version);
    if (version == GmshVersion::v2_2) {
      write_v22_body(out, mesh, groups);
    } else {
      write_v41_entities(out, mesh, groups);
      write_v41_nodes_and_elements(out, mesh, groups);
    }
    out.finish();
  });
}

}  // namespace molmesh
