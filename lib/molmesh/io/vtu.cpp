#include "molmesh/io/vtu.hpp"

#include <cstdio>
#include <ostream>

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

constexpr int kVtkTriangle = 5;
constexpr int kVtkTetra = 10;

void check_fields(const std::vector<PointField>& fields, std::size_t n_points) {
  for (const auto& f : fields) {
    if (f.name.empty()) throw Error("write_vtu: a point field has no name");
    if (f.values.size() != n_points)
      throw Error("write_vtu: point field '" + f.name + "' has " + std::to_string(f.values.size()) +
                  " values for " + std::to_string(n_points) + " points");
  }
}

std::string real(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// XML attribute values must not contain quotes or angle brackets.
std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '"':
        out += "&quot;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

struct Cells {
  std::vector<std::vector<int>> connectivity;
  std::vector<int> types;
};

void write_grid(std::ostream& out, const std::vector<Vec3>& points, const Cells& cells,
                const std::vector<std::pair<std::string, std::vector<int>>>& int_cell_data,
                const std::vector<std::pair<std::string, std::vector<int>>>& int_point_data,
                const std::vector<PointField>& fields) {
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << points.size() << "\" NumberOfCells=\""
      << cells.types.size() << "\">\n";
  out << "      <PointData>\n";
  for (const auto& [name, values] : int_point_data) {
    out << "        <DataArray type=\"Int32\" Name=\"" << escape(name) << "\" format=\"ascii\">\n";
    for (int v : values) out << v << '\n';
    out << "        </DataArray>\n";
  }
  for (const auto& f : fields) {
    out << "        <DataArray type=\"Float64\" Name=\"" << escape(f.name)
        << "\" format=\"ascii\">\n";
    for (double v : f.values) out << real(v) << '\n';
    out << "        </DataArray>\n";
  }
  out << "      </PointData>\n      <CellData>\n";
  for (const auto& [name, values] : int_cell_data) {
    out << "        <DataArray type=\"Int32\" Name=\"" << escape(name) << "\" format=\"ascii\">\n";
    for (int v : values) out << v << '\n';
    out << "        </DataArray>\n";
  }
  out << "      </CellData>\n      <Points>\n"
         "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const auto& p : points)
    out << real(p.x()) << ' ' << real(p.y()) << ' ' << real(p.z()) << '\n';
  out << "        </DataArray>\n      </Points>\n      <Cells>\n"
         "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& c : cells.connectivity) {
    for (std::size_t k = 0; k < c.size(); ++k) out << (k ? " " : "") << c[k];
    out << '\n';
  }
  out << "        </DataArray>\n"
         "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for (const auto& c : cells.connectivity) {
    offset += c.size();
    out << offset << '\n';
  }
  out << "        </DataArray>\n"
         "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for (int t : cells.types) out << t << '\n';
  out << "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
         "</VTKFile>\n";
}

}  // namespace

void write_vtu(const std::filesystem::path& path, const TetMesh& mesh,
               const std::vector<PointField>& point_fields) {
  check_fields(point_fields, mesh.points.size());
  Cells cells;
  std::vector<int> region, boundary_marker;
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& tet = mesh.tetrahedra[t];
    cells.connectivity.push_back({tet[0], tet[1], tet[2], tet[3]});
    cells.types.push_back(kVtkTetra);
    region.push_back(t < mesh.cell_markers.size() ? mesh.cell_markers[t] : 0);
    boundary_marker.push_back(0);
  }
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const auto& tri = mesh.boundary_faces[f];
    cells.connectivity.push_back({tri[0], tri[1], tri[2]});
    cells.types.push_back(kVtkTriangle);
    region.push_back(0);
    boundary_marker.push_back(f < mesh.boundary_face_markers.size() ? mesh.boundary_face_markers[f]
                                                                    : 0);
  }
  std::vector<std::pair<std::string, std::vector<int>>> point_data;
  if (mesh.vertex_markers.size() == mesh.points.size())
    point_data.emplace_back("marker", mesh.vertex_markers);
  write_file_atomically(path, [&](std::ostream& out) {
    write_grid(out, mesh.points, cells,
               {{"region", std::move(region)}, {"boundary_marker", std::move(boundary_marker)}},
               point_data, point_fields);
  });
}

void write_vtu(const std::filesystem::path& path, const SurfaceMesh& mesh,
               const std::vector<PointField>& point_fields) {
  check_fields(point_fields, mesh.points.size());
  Cells cells;
  for (const auto& tri : mesh.triangles) {
    cells.connectivity.push_back({tri[0], tri[1], tri[2]});
    cells.types.push_back(kVtkTriangle);
  }
  std::vector<std::pair<std::string, std::vector<int>>> cell_data, point_data;
  if (mesh.face_markers.size() == mesh.triangles.size())
    cell_data.emplace_back("marker", mesh.face_markers);
  if (mesh.vertex_markers.size() == mesh.points.size())
    point_data.emplace_back("marker", mesh.vertex_markers);
  write_file_atomically(path, [&](std::ostream& out) {
    write_grid(out, mesh.points, cells, cell_data, point_data, point_fields);
  });
}

}  // namespace molmesh
