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

std::string real(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
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

  write_file_atomically(path, [&](std::ostream& out) {
    out << "$MeshFormat\n"
        << (version == GmshVersion::v2_2 ? "2.2" : "4.1") << " 0 8\n$EndMeshFormat\n";
    out << "$PhysicalNames\n" << faces_by_tag.size() + tets_by_tag.size() << '\n';
    for (const auto& [tag, list] : faces_by_tag)
      out << "2 " << tag << " \"" << face_name(mesh.boundary_face_markers[list.front()]) << "\"\n";
    for (const auto& [tag, list] : tets_by_tag)
      out << "3 " << tag << " \""
          << region_name(list.front() < mesh.cell_markers.size() ? mesh.cell_markers[list.front()]
                                                                 : 0)
          << "\"\n";
    out << "$EndPhysicalNames\n";

    const std::size_t n_elements = mesh.boundary_faces.size() + mesh.tetrahedra.size();
    if (version == GmshVersion::v2_2) {
      out << "$Nodes\n" << mesh.points.size() << '\n';
      for (std::size_t i = 0; i < mesh.points.size(); ++i)
        out << i + 1 << ' ' << real(mesh.points[i].x()) << ' ' << real(mesh.points[i].y()) << ' '
            << real(mesh.points[i].z()) << '\n';
      out << "$EndNodes\n$Elements\n" << n_elements << '\n';
      std::size_t id = 1;
      for (const auto& [tag, list] : faces_by_tag)
        for (std::size_t f : list) {
          const auto& tri = mesh.boundary_faces[f];
          out << id++ << ' ' << kGmshTriangle << " 2 " << tag << ' ' << tag << ' ' << tri[0] + 1
              << ' ' << tri[1] + 1 << ' ' << tri[2] + 1 << '\n';
        }
      for (const auto& [tag, list] : tets_by_tag)
        for (std::size_t t : list) {
          const auto& tet = mesh.tetrahedra[t];
          out << id++ << ' ' << kGmshTetra << " 2 " << tag << ' ' << tag << ' ' << tet[0] + 1 << ' '
              << tet[1] + 1 << ' ' << tet[2] + 1 << ' ' << tet[3] + 1 << '\n';
        }
      out << "$EndElements\n";
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
      return real(lo.x()) + ' ' + real(lo.y()) + ' ' + real(lo.z()) + ' ' + real(hi.x()) + ' ' +
             real(hi.y()) + ' ' + real(hi.z());
    };
    out << "$Entities\n0 0 " << faces_by_tag.size() << ' ' << tets_by_tag.size() << '\n';
    for (const auto& [tag, list] : faces_by_tag)
      out << tag << ' ' << bbox([&](auto&& visit) {
        for (std::size_t f : list)
          for (int v : mesh.boundary_faces[f]) visit(v);
      }) << " 1 "
          << tag << " 0\n";
    for (const auto& [tag, list] : tets_by_tag) {
      out << tag << ' ' << bbox([&](auto&& visit) {
        for (std::size_t t : list)
          for (int v : mesh.tetrahedra[t]) visit(v);
      }) << " 1 "
          << tag << ' ' << faces_by_tag.size();
      for (const auto& face_entry : faces_by_tag) out << ' ' << face_entry.first;
      out << '\n';
    }
    out << "$EndEntities\n";
    const int node_dim = tets_by_tag.empty() ? 2 : 3;
    const int node_entity = tets_by_tag.empty()
                                ? (faces_by_tag.empty() ? 1 : faces_by_tag.begin()->first)
                                : tets_by_tag.begin()->first;
    const std::size_t n = mesh.points.size();
    out << "$Nodes\n1 " << n << " 1 " << n << '\n';
    out << node_dim << ' ' << node_entity << " 0 " << n << '\n';
    for (std::size_t i = 0; i < n; ++i) out << i + 1 << '\n';
    for (const auto& p : mesh.points)
      out << real(p.x()) << ' ' << real(p.y()) << ' ' << real(p.z()) << '\n';
    out << "$EndNodes\n";
    out << "$Elements\n"
        << faces_by_tag.size() + tets_by_tag.size() << ' ' << n_elements << " 1 " << n_elements
        << '\n';
    std::size_t id = 1;
    for (const auto& [tag, list] : faces_by_tag) {
      out << "2 " << tag << ' ' << kGmshTriangle << ' ' << list.size() << '\n';
      for (std::size_t f : list) {
        const auto& tri = mesh.boundary_faces[f];
        out << id++ << ' ' << tri[0] + 1 << ' ' << tri[1] + 1 << ' ' << tri[2] + 1 << '\n';
      }
    }
    for (const auto& [tag, list] : tets_by_tag) {
      out << "3 " << tag << ' ' << kGmshTetra << ' ' << list.size() << '\n';
      for (std::size_t t : list) {
        const auto& tet = mesh.tetrahedra[t];
        out << id++ << ' ' << tet[0] + 1 << ' ' << tet[1] + 1 << ' ' << tet[2] + 1 << ' '
            << tet[3] + 1 << '\n';
      }
    }
    out << "$EndElements\n";
  });
}

}  // namespace molmesh
