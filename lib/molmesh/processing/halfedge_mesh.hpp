#pragma once
// An editable, closed, manifold triangle mesh in the style of PMP / geometry-central, used by
// the topology-changing steps (edge flips, coarsening). Connectivity is a corner table:
// face f owns halfedges 3f, 3f+1, 3f+2, and halfedge 3f+i runs from corner i to corner
// (i+1)%3 of the face, so next/prev/face are arithmetic and only heads and twins are stored.
// Every edit goes through one gateway (replace_faces) that re-links twins and vertex
// anchors and refuses anything that would break manifoldness, so the structure can never be
// left half-edited. Removed slots stay as tombstones until to_surface_mesh() compacts.
#include <cstdint>
#include <span>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// Reusable scratch for k-ring searches: one per thread, sized lazily, so repeated queries
// allocate nothing.
struct RingScratch {
  std::vector<std::uint32_t> mark;
  std::uint32_t epoch = 0;
  std::vector<int> frontier;
};

class HalfedgeMesh {
 public:
  static constexpr int kInvalid = -1;

  // Builds connectivity from an indexed triangle list. Throws molmesh::Error if the mesh is
  // not a closed, consistently oriented 2-manifold (open or non-manifold edge, vertex whose
  // star is not a single fan, degenerate index triple, index out of range, unused vertex).
  explicit HalfedgeMesh(const SurfaceMesh& mesh);

  // --- sizes (capacities include tombstones) ------------------------------------------
  int vertex_capacity() const { return static_cast<int>(positions_.size()); }
  int face_capacity() const { return static_cast<int>(face_alive_.size()); }
  int vertex_count() const { return alive_vertices_; }
  int face_count() const { return alive_faces_; }
  bool vertex_alive(int v) const { return out_[v] != kInvalid; }
  bool face_alive(int f) const { return face_alive_[f] != 0; }

  // --- geometry -----------------------------------------------------------------------
  const Vec3& position(int v) const { return positions_[v]; }
  const std::vector<Vec3>& positions() const { return positions_; }
  void set_position(int v, const Vec3& p) { positions_[v] = p; }
  // Unnormalised face normal (twice the area vector), outward for a well-oriented face.
  Vec3 face_area_vector(int f) const;

  // --- connectivity -------------------------------------------------------------------
  static int face_of(int h) { return h / 3; }
  static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }
  int head(int h) const { return head_[h]; }
  int tail(int h) const { return head_[prev(h)]; }
  int twin(int h) const { return twin_[h]; }
  // One outgoing halfedge of a live vertex.
  int outgoing(int v) const { return out_[v]; }
  // The next outgoing halfedge counter-clockwise (seen from outside) around tail(h).
  int rotate_ccw(int h) const { return twin_[prev(h)]; }
  int face_vertex(int f, int i) const { return head_[3 * f + (i + 2) % 3]; }
  Triangle face_vertices(int f) const { return {head_[3 * f + 2], head_[3 * f], head_[3 * f + 1]}; }

  int valence(int v) const;
  // Neighbours v_1..v_M counter-clockwise seen from outside, so (v, v_i, v_i+1) are the
  // incident faces. Clears `ring` first.
  void one_ring(int v, std::vector<int>& ring) const;
  // Incident faces in the same order as one_ring (face i is (v, v_i, v_i+1)).
  void incident_faces(int v, std::vector<int>& faces) const;
  // Vertices within `rings` edges of v: v first, then by increasing edge distance.
  void k_ring(int v, int rings, RingScratch& scratch, std::vector<int>& out) const;
  // The halfedge a->b, or kInvalid if a and b are not adjacent.
  int find_halfedge(int a, int b) const;
  bool has_edge(int a, int b) const { return find_halfedge(a, b) != kInvalid; }

  // --- the mutation gateway -----------------------------------------------------------
  // Replaces the given live faces, which must form a topological disc, by `triangles`
  // (counter-clockwise, outward) covering the same boundary. Interior vertices of the old
  // disc that the new triangles no longer use are removed. Refuses (throws molmesh::Error,
  // mesh unchanged) if the new triangles do not close up exactly against the old
  // boundary, would duplicate an existing edge, or leave a vertex with fewer than three
  // neighbours. New faces take the face marker of the first replaced face.
  void replace_faces(std::span<const int> faces, std::span<const Triangle> triangles);

  // Topological edge flip (through replace_faces). can_flip says whether it is legal:
  // the new edge must not exist yet and both endpoints must keep valence >= 3.
  bool can_flip(int h) const;
  void flip_edge(int h);

  // Removes vertex v and fills its hole with `triangles`, which must use only v's one-ring
  // vertices (M - 2 triangles for valence M). Throws molmesh::Error as replace_faces does.
  void remove_vertex(int v, std::span<const Triangle> triangles);

  // Checks every invariant (twins symmetric, heads consistent, stars single fans, anchors
  // valid); throws molmesh::Error naming the first violation. For tests and debugging.
  void validate() const;

  // Compacts into a plain mesh. new_to_old[i] is the input vertex index of output vertex i
  // (vertices are never created, only removed); old_to_new is -1 for removed vertices.
  struct Compacted {
    SurfaceMesh mesh;
    std::vector<int> new_to_old;
    std::vector<int> old_to_new;
  };
  Compacted to_surface_mesh() const;

 private:
  std::vector<Vec3> positions_;
  std::vector<int> out_;   // per vertex; kInvalid marks a removed vertex
  std::vector<int> head_;  // per halfedge
  std::vector<int> twin_;  // per halfedge
  std::vector<std::uint8_t> face_alive_;
  std::vector<int> vertex_markers_;
  std::vector<int> face_markers_;
  int alive_vertices_ = 0;
  int alive_faces_ = 0;
};

}  // namespace molmesh
