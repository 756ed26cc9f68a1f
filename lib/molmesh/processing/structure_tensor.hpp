#pragma once
// Local structure tensor of GAMer Eq. 3: the sum of outer products n nᵀ of the vertex
// normals in a k-ring neighbourhood. Its eigen-structure classifies the local shape
// (plane: one large eigenvalue; ridge/valley: two; sphere/saddle: three) and steers both
// vertex relocation (Eq. 5) and coarsening (Eq. 6).
#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/processing/vertex_rings.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

struct StructureTensor {
  // λ1 ≥ λ2 ≥ λ3 ≥ 0, divided by λ1 so that λ1 == 1 (or all zero for no normals). Dividing
  // by the largest makes them independent of the neighbour count and of normal lengths,
  // keeps the paper's ratio λ2/λ1 unchanged, and reads directly as the paper's classes:
  // plane (1,0,0), ridge (1,1,0), sphere (1,1,1).
  Eigen::Vector3d eigenvalues = Eigen::Vector3d::Zero();
  // Columns e1, e2, e3 (unit, right-handed), matching the eigenvalues. Signs are fixed
  // deterministically (largest-magnitude component of e1 and e3 positive).
  Eigen::Matrix3d eigenvectors = Eigen::Matrix3d::Identity();
};

// Eq. 3 over the given normals (not necessarily unit: each contributes n nᵀ, so a longer
// normal weighs more). Eigen-decomposition by the closed-form (trigonometric) symmetric
// 3×3 solver.
StructureTensor structure_tensor_of_normals(std::span<const Vec3> normals);

// The tensor at every vertex over its `rings`-ring (the vertex itself included), from the
// unit vertex normals of vertex_normals.hpp. rings >= 1. Parallel, thread-count independent.
std::vector<StructureTensor> structure_tensors(const SurfaceMesh& mesh, int rings = 2);

// Same, over precomputed neighbourhoods (k_rings of vertex_rings.hpp), for callers that
// recompute tensors on a mesh whose connectivity does not change. With `only` (one flag per
// vertex), tensors are computed for flagged vertices only; the others are left default.
std::vector<StructureTensor> structure_tensors(const SurfaceMesh& mesh,
                                               const VertexAdjacency& neighbourhoods,
                                               std::span<const std::uint8_t> only = {});

}  // namespace molmesh
