#include "molmesh/processing/structure_tensor.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>

#include "molmesh/processing/vertex_normals.hpp"
#include "molmesh/processing/vertex_rings.hpp"

namespace molmesh {
namespace {

void fix_sign(Eigen::Ref<Eigen::Vector3d> v) {
  Eigen::Index largest = 0;
  v.cwiseAbs().maxCoeff(&largest);
  if (v[largest] < 0) v = -v;
}

StructureTensor decompose(const Eigen::Matrix3d& tensor) {
  StructureTensor result;
  const double scale = tensor.cwiseAbs().maxCoeff();
  if (!(scale > 0)) return result;
  // computeDirect is Eigen's closed-form solver (trigonometric roots of the characteristic
  // cubic, eigenvectors from cross products of the shifted rows), much faster than the
  // iterative QR for millions of 3×3 tensors. The matrix is prescaled to O(1) for accuracy.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver;
  solver.computeDirect(tensor / scale);
  // Eigen sorts ascending; we want λ1 ≥ λ2 ≥ λ3.
  const Eigen::Vector3d values = solver.eigenvalues();
  const Eigen::Matrix3d vectors = solver.eigenvectors();
  const double top = values[2];
  for (int k = 0; k < 3; ++k) {
    result.eigenvalues[k] = std::max(0.0, values[2 - k] / top);
    result.eigenvectors.col(k) = vectors.col(2 - k).normalized();
  }
  fix_sign(result.eigenvectors.col(0));
  fix_sign(result.eigenvectors.col(2));
  result.eigenvectors.col(1) = result.eigenvectors.col(2).cross(result.eigenvectors.col(0));
  return result;
}

}  // namespace

StructureTensor structure_tensor_of_normals(std::span<const Vec3> normals) {
  Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
  for (const Vec3& n : normals) tensor.noalias() += n * n.transpose();
  return decompose(tensor);
}

std::vector<StructureTensor> structure_tensors(const SurfaceMesh& mesh, int rings) {
  if (rings < 1) rings = 1;
  const VertexAdjacency faces = vertex_faces(mesh);
  return structure_tensors(mesh, k_rings(mesh, vertex_neighbours(mesh, faces), rings));
}

std::vector<StructureTensor> structure_tensors(const SurfaceMesh& mesh, const VertexAdjacency& ring,
                                               std::span<const std::uint8_t> only) {
  const std::vector<Vec3> normals = vertex_normals(mesh);
  std::vector<StructureTensor> tensors(mesh.points.size());
  const bool all = only.size() != mesh.points.size();
  tbb::parallel_for(std::size_t{0}, mesh.points.size(), [&](std::size_t v) {
    if (!all && !only[v]) return;
    Eigen::Matrix3d tensor = Eigen::Matrix3d::Zero();
    for (std::int32_t u : ring.of(v)) tensor.noalias() += normals[u] * normals[u].transpose();
    tensors[v] = decompose(tensor);
  });
  return tensors;
}

}  // namespace molmesh
