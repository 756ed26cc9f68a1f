#include "molmesh/io/vtu.hpp"

#include <ostream>

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/text_output.hpp"

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

// Cells in VTK's own layout: flat connectivity, end offsets, one type per cell.
struct Cells {
  std::vector<int> connectivity;
  std::vector<std::size_t> offsets;
  std::vector<int> types;

  template <class Corners>
  void add(const Corners& corners, int type) {
    connectivity.insert(connectivity.end(), corners.begin(), corners.end());
    offsets.push_back(connectivity.size());
    types.push_back(type);
  }
};

void write_grid(std::ostream& stream, const std::vector<Vec3>& points, const Cells& cells,
                const std::vector<std::pair<std::string, std::vector<int>>>& int_cell_data,
                const std::vector<std::pair<std::string, std::vector<int>>>& int_point_data,
                const std::vector<PointField>& fields) {
  io_detail::TextOutput out(stream);
  auto int_array = [&](const std::string& name, const std::vector<int>& values) {
    out.text("        <DataArray type=\"Int32\" Name=\"")
        .text(escape(name))
        .text("\" format=\"ascii\">\n");
    for (int v : values) out.integer(v).ch('\n');
    out.text("        </DataArray>\n");
  };
  out.text(
         "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
         "    <Piece NumberOfPoints=\"")
      .integer(points.size())
      .text("\" NumberOfCells=\"")
      .integer(cells.types.size())
      .text("\">\n      <PointData>\n");
  for (const auto& [name, values] : int_point_data) int_array(name, values);
  for (const auto& f : fields) {
    out.text("        <DataArray type=\"Float64\" Name=\"")
        .text(escape(f.name))
        .text("\" format=\"ascii\">\n");
    for (double v : f.values) out.general(v, 9).ch('\n');
    out.text("        </DataArray>\n");
  }
  out.text("      </PointData>\n      <CellData>\n");
  for (const auto& [name, values] : int_cell_data) int_array(name, values);
  out.text(
      "      </CellData>\n      <Points>\n"
      "        <DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
  for (const auto& p : points)
    out.general(p.x(), 9).ch(' ').general(p.y(), 9).ch(' ').general(p.z(), 9).ch('\n');
  out.text(
      "        </DataArray>\n      </Points>\n      <Cells>\n"
      "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  std::size_t begin = 0;
  for (const std::size_t end : cells.offsets) {
    for (std::size_t k = begin; k < end; ++k) {
      if (k > begin) out.ch(' ');
      out.integer(cells.connectivity[k]);
    }
    out.ch('\n');
    begin = end;
  }
  out.text(
      "        </DataArray>\n"
      "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (const std::size_t end : cells.offsets) out.integer(end).ch('\n');
  out.text(
      "        </DataArray>\n"
      "        <DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (int t : cells.types) out.integer(t).ch('\n');
  out.text(
      "        </DataArray>\n      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
      "</VTKFile>\n");
  out.finish();
}

}  // namespace

void write_vtu(const std::filesystem::path& path, const TetMesh& mesh,
               const std::vector<PointField>& point_fields) {
  check_fields(point_fields, mesh.points.size());
  Cells cells;
  std::vector<int> region, boundary_marker;
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& tet = mesh.tetrahedra[t];
    cells.add(tet, kVtkTetra);
    region.push_back(t < mesh.cell_markers.size() ? mesh.cell_markers[t] : 0);
    boundary_marker.push_back(0);
  }
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const auto& tri = mesh.boundary_faces[f];
    cells.add(tri, kVtkTriangle);
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
    cells.add(tri, kVtkTriangle);
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
