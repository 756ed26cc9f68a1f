#pragma once
// A coarser hierarchy level that multigrid discretises on its own mesh instead of taking
// the Galerkin product P^T A P (multigrid.hpp, MeshOperator). Shared by every physics
// solver: Smoluchowski samples its potential there; Poisson needs only the mesh (its
// charges load the finest level alone).
#include <span>

#include "molmesh/tetmesh/tet_mesh.hpp"

namespace molmesh::solvers {

struct CoarseLevel {
  const TetMesh* mesh = nullptr;
  std::span<const double> beta_w;  // beta*W at its vertices (Smoluchowski); empty: none
};

}  // namespace molmesh::solvers
