#pragma once
// Neighbourhoods over a fixed SurfaceMesh (no editing): vertex→faces, ordered one-rings,
// and k-rings. Processing steps that only move vertices use these instead of a halfedge
// structure.
#include <cstdint>
#include <span>
#include <vector>

#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// Compressed adjacency: the items of vertex v are items[offsets[v] .. offsets[v+1]).
struct VertexAdjacency {
  std::vector<std::int32_t> offsets;
  std::vector<std::int32_t> items;

  std::size_t vertex_count() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  std::span<const std::int32_t> of(std::size_t v) const {
    return {items.data() + offsets[v], items.data() + offsets[v + 1]};
  }
};

// Faces incident to each vertex, in increasing face index.
VertexAdjacency vertex_faces(const SurfaceMesh& mesh);

// For each vertex, its neighbours v_1..v_M in counter-clockwise order seen from outside
// (so that (x, v_i, v_{i+1}) is an incident triangle). For a vertex whose star is not a
// single closed fan (boundary, non-manifold), the ring is empty: callers leave such
// vertices alone. Deterministic: starts at the neighbour of the lowest-index face.
VertexAdjacency ordered_one_rings(const SurfaceMesh& mesh, const VertexAdjacency& faces);

// Neighbours of each vertex (sharing an edge), sorted, also for non-manifold vertices.
VertexAdjacency vertex_neighbours(const SurfaceMesh& mesh, const VertexAdjacency& faces);

// Vertices within `rings` edges of each vertex (the vertex itself first, then by
// increasing distance in edges, ties in increasing index). rings >= 1.
VertexAdjacency k_rings(const SurfaceMesh& mesh, const VertexAdjacency& neighbours, int rings);

}  // namespace molmesh
