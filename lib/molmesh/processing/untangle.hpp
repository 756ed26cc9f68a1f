#pragma once
// Undoing the rare self-intersections processing creates. Where two sheets of a surface come
// within a fraction of an edge of each other (narrow clefts at strongly negative
// blobbyness, e.g. fas2 at B = -2), vertex moves on both sides can push one through the
// other; TetGen then cannot mesh the surface. The input surface (marching cubes) does not
// intersect itself, so the vertices of crossing triangles are moved back towards where they
// came from until no crossing is left.
#include <cstddef>
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// Moves the vertices of crossing triangles of `mesh` halfway back to their positions in
// `input` (provenance[v] = input vertex of v), then all the way, for a bounded number of
// rounds; crossings left then are folds of the coarser connectivity, and the vertices of
// the crossing triangles move to the mean of their neighbours, again for a bounded number of
// rounds. Returns the number of crossing triangle pairs left (0: untangled).
std::size_t untangle(SurfaceMesh& mesh, const SurfaceMesh& input,
                     const std::vector<int>& provenance);

}  // namespace molmesh
