#pragma once
// Marching cubes on a Grid: the isosurface F = isovalue as a closed, consistently oriented
// 2-manifold with outward normals (pointing towards lower F). Decisions (ambiguities, exact
// isovalue hits, vertex placement) are in docs/surface.md.
#include "molmesh/core/reporter.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh {

// Samples with value >= isovalue are inside. The grid is treated as surrounded by one layer
// of outside samples, so the result is closed even when the inside touches the boundary
// (a warning is reported then). One vertex per crossed grid edge, shared between cubes;
// rarely (ambiguous faces) a cube adds one vertex at the centroid of a polygon to stay
// manifold. Vertices lie at least 1e-3 cell from grid nodes, so no triangle has zero area.
// Deterministic: the output does not depend on the number of threads.
SurfaceMesh marching_cubes(const Grid& grid, double isovalue, const Reporter& reporter = {});

}  // namespace molmesh
