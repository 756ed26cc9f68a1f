#pragma once
// VTK XML unstructured grids (.vtu, ASCII), for ParaView and meshio.
#include <filesystem>
#include <string>
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh {

// A named scalar per point (e.g. a potential from the solver).
struct PointField {
  std::string name;
  std::vector<double> values;  // one per point
};

// Tetrahedra with cell data "region", point data "marker" and the given fields, followed
// by the boundary faces as triangle cells (region 0) with cell data "boundary_marker"
// (0 on tetrahedra), so the surfaces can be shown by thresholding. Throws molmesh::Error
// if a field has the wrong length, OutputError if the file cannot be written.
void write_vtu(const std::filesystem::path& path, const TetMesh& mesh,
               const std::vector<PointField>& point_fields = {});

// A surface as triangle cells, with "marker" point/cell data when present.
void write_vtu(const std::filesystem::path& path, const SurfaceMesh& mesh,
               const std::vector<PointField>& point_fields = {});

}  // namespace molmesh
