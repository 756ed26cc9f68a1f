#include "molmesh/io/hierarchy_validate.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>

#include "molmesh/io/hdf5_file.hpp"
#include "molmesh/io/hierarchy_layout.hpp"
#include "molmesh/tetmesh/markers.hpp"

namespace molmesh::hierarchy_file {
namespace {

using hdf5::H5Failure;

// rather than produce garbage or crash later.
void check_finite(const std::vector<Vec3>& points, const std::string& what) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      throw H5Failure(what + ": point " + std::to_string(i) + " is not finite");
}

void check_length(std::size_t got, std::size_t want, const std::string& what, bool may_be_empty) {
  if (got == want || (may_be_empty && got == 0)) return;
  throw H5Failure(what + " has " + std::to_string(got) + " values, expected " +
                  std::to_string(want));
}

void check_values(const std::vector<int>& values, std::initializer_list<int> allowed,
                  const std::string& what) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (std::find(allowed.begin(), allowed.end(), values[i]) == allowed.end())
      throw H5Failure(what + "[" + std::to_string(i) + "] = " + std::to_string(values[i]) +
                      " is not a valid marker");
}

// Every vertex index of `cells` is below n.
template <class Cells>
void check_range(const Cells& cells, std::size_t n, const std::string& what) {
  for (const auto& cell : cells) {
    for (int v : cell) {
      if (v < 0 || static_cast<std::size_t>(v) >= n) {
        throw H5Failure(what + ": vertex index out of range");
      }
    }
  }
}

}  // namespace

void validate_level(const HierarchyLevel& level, const std::string& base) {
  using namespace markers;
  check_range(level.surface.triangles, level.surface.points.size(), base + "/surface/triangles");
  check_range(level.volume.tetrahedra, level.volume.points.size(), base + "/volume/tetrahedra");
  check_range(level.volume.boundary_faces, level.volume.points.size(),
              base + "/volume/boundary_faces");
  if (!std::isfinite(level.t0)) throw H5Failure(base + ": t0 is not finite");
  const SurfaceMesh& s = level.surface;
  check_finite(s.points, base + "/surface/points");
  check_length(s.vertex_markers.size(), s.points.size(), base + "/surface/vertex_markers", true);
  check_length(s.face_markers.size(), s.triangles.size(), base + "/surface/face_markers", true);
  const TetMesh& v = level.volume;
  const std::string volume = base + "/volume/";
  check_finite(v.points, volume + "points");
  check_length(v.cell_markers.size(), v.tetrahedra.size(), volume + "cell_markers", false);
  check_values(v.cell_markers, {kMoleculeRegion, kSolventRegion}, volume + "cell_markers");
  check_length(v.vertex_markers.size(), v.points.size(), volume + "vertex_markers", false);
  check_values(v.vertex_markers, {kNoMarker, kMolecularSurface, kOuterSphere, kActiveSite},
               volume + "vertex_markers");
  check_length(v.boundary_face_markers.size(), v.boundary_faces.size(),
               volume + "boundary_face_markers", false);
  check_values(v.boundary_face_markers, {kNoMarker, kMolecularSurface, kOuterSphere, kActiveSite},
               volume + "boundary_face_markers");
  const auto& permutation = level.volume_permutation;
  check_length(permutation.size(), v.points.size(), volume + "permutation", true);
  std::vector<char> seen(permutation.size(), 0);
  for (std::size_t i = 0; i < permutation.size(); ++i) {
    const int p = permutation[i];
    if (p < 0 || static_cast<std::size_t>(p) >= permutation.size() || seen[p])
      throw H5Failure(volume + "permutation[" + std::to_string(i) + "] = " + std::to_string(p) +
                      " is not a permutation of 0.." + std::to_string(permutation.size() - 1));
    seen[p] = 1;
  }
}

void validate_csr(const std::string& group_path, const std::vector<std::int64_t>& shape,
                  const std::vector<double>& data, const std::vector<int>& indices,
                  const std::vector<std::int64_t>& indptr) {
  if (indptr.size() != static_cast<std::size_t>(shape[0]) + 1 || indices.size() != data.size() ||
      indptr.front() != 0 || indptr.back() != static_cast<std::int64_t>(data.size())) {
    throw H5Failure(group_path + ": inconsistent CSR arrays");
  }
  for (std::size_t i = 1; i < indptr.size(); ++i)
    if (indptr[i] < indptr[i - 1]) throw H5Failure(group_path + ": bad indptr");
  for (int column : indices) {
    if (column < 0 || column >= shape[1]) throw H5Failure(group_path + ": column out of range");
  }
}

void validate_transfer(const LevelTransfer& transfer, const HierarchyLevel& fine_level,
                       const HierarchyLevel& coarse_level, int fine_index,
                       const std::string& base) {
  if (transfer.volume.rows() != static_cast<Eigen::Index>(fine_level.volume.points.size()) ||
      transfer.volume.cols() != static_cast<Eigen::Index>(coarse_level.volume.points.size()) ||
      transfer.surface.rows() != static_cast<Eigen::Index>(fine_level.surface.points.size()) ||
      transfer.surface.cols() != static_cast<Eigen::Index>(coarse_level.surface.points.size())) {
    throw H5Failure(base + ": matrix shape does not match the level sizes");
  }
  for (const SparseMatrix* m : {&transfer.volume, &transfer.surface})
    for (Eigen::Index k = 0; k < m->nonZeros(); ++k)
      if (!std::isfinite(m->valuePtr()[k]))
        throw H5Failure(base + ": a prolongation weight is not finite");
  const auto& provenance = coarse_level.surface_provenance;
  check_length(provenance.size(), coarse_level.surface.points.size(),
               level_path(fine_index + 1) + "/surface/provenance", true);
  for (int p : provenance)
    if (p < 0 || static_cast<std::size_t>(p) >= fine_level.surface.points.size())
      throw H5Failure(level_path(fine_index + 1) + "/surface/provenance: vertex " +
                      std::to_string(p) + " out of range");
}

}  // namespace molmesh::hierarchy_file
