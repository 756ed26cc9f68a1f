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

}  // namespace

void write_gmsh(const std::filesystem::path& path, const TetMesh& mesh, GmshVersion version) {
  if (mesh.boundary_face_markers.size() != mesh.boundary_faces.size())
    throw Error("write_gmsh: boundary face markers do not match the faces");
  auto region_of = [&](std::size_t t) {
    return physical_tag(t < mesh.cell_markers.size() ? mesh.cell_markers[t] : 0);
  };
  // Faces and tets grouped by tag (std::map: ascending, deterministic).
  std::map<int, std::vector<std::size_t>> faces_by_tag, tets_by_tag;
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f)
    faces_by_tag[physical_tag(mesh.boundary_face_markers[f])].push_back(f);
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) tets_by_tag[region_of(t)].push_back(t);

  write_file_atomically(path, [&](std::ostream& stream) {
    io_detail::TextOutput out(stream);
    auto point = [&](const Vec3& p) {
      out.general(p.x(), 12).ch(' ').general(p.y(), 12).ch(' ').general(p.z(), 12);
    };
    out.text("$MeshFormat\n")
        .text(version == GmshVersion::v2_2 ? "2.2" : "4.1")
        .text(" 0 8\n$EndMeshFormat\n$PhysicalNames\n")
        .integer(faces_by_tag.size() + tets_by_tag.size())
        .ch('\n');
    for (const auto& [tag, list] : faces_by_tag)
      out.text("2 ")
          .integer(tag)
          .text(" \"")
          .text(face_name(mesh.boundary_face_markers[list.front()]))
          .text("\"\n");
    for (const auto& [tag, list] : tets_by_tag)
      out.text("3 ")
          .integer(tag)
          .text(" \"")
          .text(region_name(
              list.front() < mesh.cell_markers.size() ? mesh.cell_markers[list.front()] : 0))
          .text("\"\n");
    out.text("$EndPhysicalNames\n");

    const std::size_t n_elements = mesh.boundary_faces.size() + mesh.tetrahedra.size();
    if (version == GmshVersion::v2_2) {
      out.text("$Nodes\n").integer(mesh.points.size()).ch('\n');
      for (std::size_t i = 0; i < mesh.points.size(); ++i) {
        out.integer(i + 1).ch(' ');
        point(mesh.points[i]);
        out.ch('\n');
      }
      out.text("$EndNodes\n$Elements\n").integer(n_elements).ch('\n');
      std::size_t id = 1;
      for (const auto& [tag, list] : faces_by_tag)
        for (std::size_t f : list) {
          out.integer(id++)
              .ch(' ')
              .integer(kGmshTriangle)
              .text(" 2 ")
              .integer(tag)
              .ch(' ')
              .integer(tag);
          for (int v : mesh.boundary_faces[f]) out.ch(' ').integer(v + 1);
          out.ch('\n');
        }
      for (const auto& [tag, list] : tets_by_tag)
        for (std::size_t t : list) {
          out.integer(id++)
              .ch(' ')
              .integer(kGmshTetra)
              .text(" 2 ")
              .integer(tag)
              .ch(' ')
              .integer(tag);
          for (int v : mesh.tetrahedra[t]) out.ch(' ').integer(v + 1);
          out.ch('\n');
        }
      out.text("$EndElements\n");
      out.finish();
      return;
    }

    // 4.1: one geometric entity per physical group (entity tag = physical tag), each with
    // a bounding box; all nodes in one block on the first volume (or surface) entity.
    auto bbox = [&](auto&& for_each_vertex) {
      Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
      Vec3 hi = -lo;
      for_each_vertex([&](int v) {
        lo = lo.cwiseMin(mesh.points[v]);
        hi = hi.cwiseMax(mesh.points[v]);
      });
      point(lo);
      out.ch(' ');
      point(hi);
    };
    out.text("$Entities\n0 0 ")
        .integer(faces_by_tag.size())
        .ch(' ')
        .integer(tets_by_tag.size())
        .ch('\n');
    // clang 14 cannot capture structured bindings in a lambda (P1091 came in clang 16).
    for (const auto& entry : faces_by_tag) {
      const int tag = entry.first;
      out.integer(tag).ch(' ');
      bbox([&, &list = entry.second](auto&& visit) {
        for (std::size_t f : list)
          for (int v : mesh.boundary_faces[f]) visit(v);
      });
      out.text(" 1 ").integer(tag).text(" 0\n");
    }
    for (const auto& entry : tets_by_tag) {
      const int tag = entry.first;
      out.integer(tag).ch(' ');
      bbox([&, &list = entry.second](auto&& visit) {
        for (std::size_t t : list)
          for (int v : mesh.tetrahedra[t]) visit(v);
      });
      out.text(" 1 ").integer(tag).ch(' ').integer(faces_by_tag.size());
      for (const auto& face_entry : faces_by_tag) out.ch(' ').integer(face_entry.first);
      out.ch('\n');
    }
    out.text("$EndEntities\n");
    const int node_dim = tets_by_tag.empty() ? 2 : 3;
    const int node_entity = tets_by_tag.empty()
                                ? (faces_by_tag.empty() ? 1 : faces_by_tag.begin()->first)
                                : tets_by_tag.begin()->first;
    const std::size_t n = mesh.points.size();
    out.text("$Nodes\n1 ").integer(n).text(" 1 ").integer(n).ch('\n');
    out.integer(node_dim).ch(' ').integer(node_entity).text(" 0 ").integer(n).ch('\n');
    for (std::size_t i = 0; i < n; ++i) out.integer(i + 1).ch('\n');
    for (const auto& p : mesh.points) {
      point(p);
      out.ch('\n');
    }
    out.text("$EndNodes\n$Elements\n")
        .integer(faces_by_tag.size() + tets_by_tag.size())
        .ch(' ')
        .integer(n_elements)
        .text(" 1 ")
        .integer(n_elements)
        .ch('\n');
    std::size_t id = 1;
    for (const auto& [tag, list] : faces_by_tag) {
      out.text("2 ")
          .integer(tag)
          .ch(' ')
          .integer(kGmshTriangle)
          .ch(' ')
          .integer(list.size())
          .ch('\n');
      for (std::size_t f : list) {
        out.integer(id++);
        for (int v : mesh.boundary_faces[f]) out.ch(' ').integer(v + 1);
        out.ch('\n');
      }
    }
    for (const auto& [tag, list] : tets_by_tag) {
      out.text("3 ").integer(tag).ch(' ').integer(kGmshTetra).ch(' ').integer(list.size()).ch('\n');
      for (std::size_t t : list) {
        out.integer(id++);
        for (int v : mesh.tetrahedra[t]) out.ch(' ').integer(v + 1);
        out.ch('\n');
      }
    }
    out.text("$EndElements\n");
    out.finish();
  });
}

}  // namespace molmesh
