#include "molmesh/processing/halfedge_mesh.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <string>
#include <utility>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

std::string vertex_text(int v) { return "vertex " + std::to_string(v); }

}  // namespace

HalfedgeMesh::HalfedgeMesh(const SurfaceMesh& mesh) {
  const std::size_t n = mesh.points.size();
  const std::size_t m = mesh.triangles.size();
  if (n > static_cast<std::size_t>(INT32_MAX / 2) || m > static_cast<std::size_t>(INT32_MAX / 4)) {
    throw Error("surface mesh too large for the editable mesh (more than 2^29 triangles)");
  }
  positions_ = mesh.points;
  out_.assign(n, kInvalid);
  head_.resize(3 * m);
  twin_.assign(3 * m, kInvalid);
  face_alive_.assign(m, 1);
  if (mesh.vertex_markers.size() == n) vertex_markers_ = mesh.vertex_markers;
  if (mesh.face_markers.size() == m) face_markers_ = mesh.face_markers;

  const int vn = static_cast<int>(n);
  for (std::size_t f = 0; f < m; ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int i = 0; i < 3; ++i) {
      if (t[i] < 0 || t[i] >= vn) {
        throw Error("surface mesh triangle " + std::to_string(f) + " refers to vertex " +
                    std::to_string(t[i]) + ", but there are only " + std::to_string(n) +
                    " vertices");
      }
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
      throw Error("surface mesh triangle " + std::to_string(f) +
                  " repeats a vertex; remove degenerate triangles first");
    }
    for (int i = 0; i < 3; ++i) {
      head_[3 * f + i] = t[(i + 1) % 3];
      out_[t[i]] = static_cast<int>(3 * f + i);
    }
  }

  // Pair halfedges by their undirected edge: exactly two, running in opposite directions.
  std::vector<std::pair<std::uint64_t, int>> keyed(3 * m);
  for (std::size_t h = 0; h < 3 * m; ++h) {
    const auto a = static_cast<std::uint64_t>(tail(static_cast<int>(h)));
    const auto b = static_cast<std::uint64_t>(head_[h]);
    keyed[h] = {std::min(a, b) << 32 | std::max(a, b), static_cast<int>(h)};
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < keyed.size();) {
    std::size_t j = i;
    while (j < keyed.size() && keyed[j].first == keyed[i].first) ++j;
    const int a = static_cast<int>(keyed[i].first >> 32);
    const int b = static_cast<int>(keyed[i].first & 0xffffffffu);
    const std::string edge = "edge " + std::to_string(a) + "-" + std::to_string(b);
    if (j - i == 1) {
      throw Error("surface mesh is not closed: " + edge +
                  " belongs to one triangle only; close holes before processing");
    }
    if (j - i > 2) {
      throw Error("surface mesh is not manifold: " + edge + " is shared by " +
                  std::to_string(j - i) + " triangles");
    }
    const int h0 = keyed[i].second;
    const int h1 = keyed[i + 1].second;
    if (tail(h0) == tail(h1)) {
      throw Error("surface mesh is not consistently oriented at " + edge +
                  "; orient all triangles counter-clockwise seen from outside");
    }
    twin_[h0] = h1;
    twin_[h1] = h0;
    i = j;
  }

  // Each vertex star must be one closed fan; a pinched vertex (two fans) is non-manifold.
  std::vector<int> outgoing_count(n, 0);
  for (std::size_t h = 0; h < 3 * m; ++h) ++outgoing_count[tail(static_cast<int>(h))];
  for (int v = 0; v < vn; ++v) {
    if (out_[v] == kInvalid) continue;  // unused vertex: dropped, as if removed
    ++alive_vertices_;
    int count = 0;
    int h = out_[v];
    do {
      ++count;
      h = rotate_ccw(h);
    } while (h != out_[v] && count <= outgoing_count[v]);
    if (count != outgoing_count[v]) {
      throw Error("surface mesh is not manifold at " + vertex_text(v) +
                  ": its triangles form more than one fan");
    }
  }
  alive_faces_ = static_cast<int>(m);
}

Vec3 HalfedgeMesh::face_area_vector(int f) const {
  const Vec3& a = positions_[head_[3 * f + 2]];
  const Vec3& b = positions_[head_[3 * f]];
  const Vec3& c = positions_[head_[3 * f + 1]];
  return (b - a).cross(c - a);
}

int HalfedgeMesh::valence(int v) const {
  int count = 0;
  int h = out_[v];
  do {
    ++count;
    h = rotate_ccw(h);
  } while (h != out_[v]);
  return count;
}

void HalfedgeMesh::one_ring(int v, std::vector<int>& ring) const {
  ring.clear();
  int h = out_[v];
  do {
    ring.push_back(head_[h]);
    h = rotate_ccw(h);
  } while (h != out_[v]);
}

void HalfedgeMesh::incident_faces(int v, std::vector<int>& faces) const {
  faces.clear();
  int h = out_[v];
  do {
    faces.push_back(face_of(h));
    h = rotate_ccw(h);
  } while (h != out_[v]);
}

void HalfedgeMesh::k_ring(int v, int rings, RingScratch& scratch, std::vector<int>& out) const {
  if (scratch.mark.size() < positions_.size()) scratch.mark.assign(positions_.size(), 0);
  if (++scratch.epoch == 0) {  // wrapped: old marks could collide with the new epoch
    std::fill(scratch.mark.begin(), scratch.mark.end(), 0);
    scratch.epoch = 1;
  }
  const std::uint32_t epoch = scratch.epoch;
  out.clear();
  out.push_back(v);
  scratch.mark[v] = epoch;
  std::size_t begin = 0;
  for (int r = 0; r < rings; ++r) {
    const std::size_t end = out.size();
    for (std::size_t i = begin; i < end; ++i) {
      const int u = out[i];
      int h = out_[u];
      do {
        const int w = head_[h];
        if (scratch.mark[w] != epoch) {
          scratch.mark[w] = epoch;
          out.push_back(w);
        }
        h = rotate_ccw(h);
      } while (h != out_[u]);
    }
    begin = end;
  }
}

int HalfedgeMesh::find_halfedge(int a, int b) const {
  int h = out_[a];
  do {
    if (head_[h] == b) return h;
    h = rotate_ccw(h);
  } while (h != out_[a]);
  return kInvalid;
}

void HalfedgeMesh::replace_faces(std::span<const int> faces, std::span<const Triangle> triangles) {
  auto in_old = [&](int f) { return std::find(faces.begin(), faces.end(), f) != faces.end(); };
  for (int f : faces) {
    if (f < 0 || f >= face_capacity() || !face_alive(f)) {
      throw Error("replace_faces: face " + std::to_string(f) + " is not a live face");
    }
  }

  // Boundary of the old disc: halfedges whose twin lies outside it.
  struct Boundary {
    int tail, head, outer;
    bool used;
  };
  // Reused per thread: hundreds of thousands of edits must not each allocate.
  static thread_local std::vector<Boundary> boundary;
  static thread_local std::vector<int> old_vertices;
  boundary.clear();
  old_vertices.clear();
  for (int f : faces) {
    for (int i = 0; i < 3; ++i) {
      const int h = 3 * f + i;
      if (!in_old(face_of(twin_[h]))) boundary.push_back({tail(h), head_[h], twin_[h], false});
      old_vertices.push_back(head_[h]);
    }
  }
  std::sort(old_vertices.begin(), old_vertices.end());
  old_vertices.erase(std::unique(old_vertices.begin(), old_vertices.end()), old_vertices.end());
  auto is_old_vertex = [&](int v) {
    return std::binary_search(old_vertices.begin(), old_vertices.end(), v);
  };

  // Each new halfedge is either inner (its reverse is also new) or matches exactly one old
  // boundary halfedge; anything else would open or pinch the surface.
  const std::size_t nh = 3 * triangles.size();
  static thread_local std::vector<int> partner;  // inner: index of reverse; boundary: -2 - i
  partner.assign(nh, kInvalid);
  auto new_tail = [&](std::size_t k) { return triangles[k / 3][k % 3]; };
  auto new_head = [&](std::size_t k) { return triangles[k / 3][(k % 3 + 1) % 3]; };
  for (std::size_t k = 0; k < nh; ++k) {
    const int a = new_tail(k);
    const int b = new_head(k);
    if (a == b) throw Error("replace_faces: degenerate new triangle");
    if (!is_old_vertex(a)) {
      throw Error("replace_faces: new triangle uses " + vertex_text(a) + " outside the region");
    }
    for (std::size_t q = 0; q < nh; ++q) {
      if (q == k) continue;
      if (new_tail(q) == a && new_head(q) == b) {
        throw Error("replace_faces: new triangles repeat the oriented edge " + std::to_string(a) +
                    "-" + std::to_string(b));
      }
      if (new_tail(q) == b && new_head(q) == a) partner[k] = static_cast<int>(q);
    }
    if (partner[k] != kInvalid) continue;
    bool matched = false;
    for (std::size_t i = 0; i < boundary.size(); ++i) {
      if (boundary[i].tail == a && boundary[i].head == b && !boundary[i].used) {
        boundary[i].used = true;
        partner[k] = -2 - static_cast<int>(i);
        matched = true;
        break;
      }
    }
    if (!matched) {
      throw Error("replace_faces: new edge " + std::to_string(a) + "-" + std::to_string(b) +
                  " is neither inside the region nor on its boundary");
    }
  }
  for (const Boundary& b : boundary) {
    if (!b.used) throw Error("replace_faces: new triangles leave the region boundary open");
  }
  // A new inner edge must not duplicate an edge that survives outside the region.
  for (std::size_t k = 0; k < nh; ++k) {
    if (partner[k] < 0) continue;
    const int a = new_tail(k);
    const int b = new_head(k);
    if (a > b) continue;
    const int h = find_halfedge(a, b);
    if (h != kInvalid && !(in_old(face_of(h)) && in_old(face_of(twin_[h])))) {
      throw Error("replace_faces: edge " + std::to_string(a) + "-" + std::to_string(b) +
                  " already exists; the edit would make the surface non-manifold");
    }
  }

  // Predict every star: count faces per vertex after the edit, and check that kept inner
  // vertices and boundary vertices keep at least 3 neighbours.
  static thread_local std::vector<int> faces_after;
  faces_after.assign(old_vertices.size(), 0);
  for (std::size_t i = 0; i < old_vertices.size(); ++i) {
    const int v = old_vertices[i];
    int count = valence(v);  // faces around v before
    for (int f : faces) {
      for (int c = 0; c < 3; ++c) count -= head_[3 * f + c] == v ? 1 : 0;
    }
    for (const Triangle& t : triangles) {
      for (int c = 0; c < 3; ++c) count += t[c] == v ? 1 : 0;
    }
    faces_after[i] = count;
    const bool on_boundary = std::any_of(boundary.begin(), boundary.end(),
                                         [&](const Boundary& b) { return b.tail == v; });
    if ((on_boundary || count > 0) && count < 3) {
      throw Error("replace_faces: the edit would leave " + vertex_text(v) +
                  " with fewer than 3 neighbours");
    }
  }

  // Snapshot for rollback in case a star turns out pinched (several fans).
  const int old_capacity = face_capacity();
  static thread_local std::vector<int> saved_heads, saved_twins;
  saved_heads.clear();
  saved_twins.clear();
  for (int f : faces) {
    for (int c = 0; c < 3; ++c) {
      saved_heads.push_back(head_[3 * f + c]);
      saved_twins.push_back(twin_[3 * f + c]);
    }
  }
  static thread_local std::vector<int> saved_out;
  saved_out.clear();
  for (int v : old_vertices) saved_out.push_back(out_[v]);
  const int saved_marker = face_markers_.empty() ? 0 : face_markers_[faces.empty() ? 0 : faces[0]];
  // The reused slots take saved_marker below; a rollback gives them their own back.
  static thread_local std::vector<int> saved_face_markers;
  saved_face_markers.clear();
  if (!face_markers_.empty())
    for (int f : faces) saved_face_markers.push_back(face_markers_[f]);

  // Slots: reuse the old faces' slots, append if more triangles than before.
  static thread_local std::vector<int> slots;
  slots.assign(triangles.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (t < faces.size()) {
      slots[t] = faces[t];
    } else {
      slots[t] = face_capacity();
      head_.resize(head_.size() + 3, kInvalid);
      twin_.resize(twin_.size() + 3, kInvalid);
      face_alive_.push_back(0);
      if (!face_markers_.empty()) face_markers_.push_back(saved_marker);
    }
  }
  for (std::size_t t = triangles.size(); t < faces.size(); ++t) {
    const int f = faces[t];
    face_alive_[f] = 0;
    for (int c = 0; c < 3; ++c) head_[3 * f + c] = twin_[3 * f + c] = kInvalid;
  }
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const int f = slots[t];
    face_alive_[f] = 1;
    if (!face_markers_.empty()) face_markers_[f] = saved_marker;
    for (int c = 0; c < 3; ++c) head_[3 * f + c] = triangles[t][(c + 1) % 3];
  }
  auto slot_halfedge = [&](std::size_t k) { return 3 * slots[k / 3] + static_cast<int>(k % 3); };
  for (std::size_t k = 0; k < nh; ++k) {
    const int h = slot_halfedge(k);
    if (partner[k] >= 0) {
      twin_[h] = slot_halfedge(static_cast<std::size_t>(partner[k]));
    } else {
      const int outer = boundary[static_cast<std::size_t>(-2 - partner[k])].outer;
      twin_[h] = outer;
      twin_[outer] = h;
    }
  }
  for (int v : old_vertices) out_[v] = kInvalid;
  for (std::size_t k = 0; k < nh; ++k) out_[new_tail(k)] = slot_halfedge(k);

  // Verify that each star is a single fan with the predicted number of faces.
  bool pinched = false;
  for (std::size_t i = 0; i < old_vertices.size() && !pinched; ++i) {
    const int v = old_vertices[i];
    if (out_[v] == kInvalid) continue;
    int count = 0;
    int h = out_[v];
    do {
      ++count;
      h = rotate_ccw(h);
    } while (h != out_[v] && count <= faces_after[i]);
    pinched = count != faces_after[i];
  }
  if (pinched) {
    std::size_t s = 0;
    for (std::size_t i = 0; i < saved_face_markers.size(); ++i)
      face_markers_[faces[i]] = saved_face_markers[i];
    for (int f : faces) {
      face_alive_[f] = 1;
      for (int c = 0; c < 3; ++c, ++s) {
        head_[3 * f + c] = saved_heads[s];
        twin_[3 * f + c] = saved_twins[s];
        twin_[saved_twins[s]] = 3 * f + c;
      }
    }
    for (std::size_t i = 0; i < old_vertices.size(); ++i) out_[old_vertices[i]] = saved_out[i];
    head_.resize(3 * static_cast<std::size_t>(old_capacity));
    twin_.resize(3 * static_cast<std::size_t>(old_capacity));
    face_alive_.resize(static_cast<std::size_t>(old_capacity));
    if (!face_markers_.empty()) face_markers_.resize(static_cast<std::size_t>(old_capacity));
    throw Error("replace_faces: the new triangles would pinch a vertex (non-manifold)");
  }

  for (int v : old_vertices) {
    if (out_[v] == kInvalid) --alive_vertices_;
  }
  alive_faces_ += static_cast<int>(triangles.size()) - static_cast<int>(faces.size());
}

bool HalfedgeMesh::can_flip(int h) const {
  const int a = tail(h);
  const int b = head_[h];
  const int c = head_[next(h)];
  const int d = head_[next(twin_[h])];
  if (c == d) return false;
  if (valence(a) <= 3 || valence(b) <= 3) return false;
  return !has_edge(c, d);
}

void HalfedgeMesh::flip_edge(int h) {
  const int t = twin_[h];
  const int a = tail(h);
  const int b = head_[h];
  const int c = head_[next(h)];
  const int d = head_[next(t)];
  // Quad a, d, b, c (counter-clockwise); the new diagonal c-d splits it.
  const int old_faces[2] = {face_of(h), face_of(t)};
  const Triangle new_faces[2] = {Triangle{a, d, c}, Triangle{d, b, c}};
  replace_faces(old_faces, new_faces);
}

void HalfedgeMesh::remove_vertex(int v, std::span<const Triangle> triangles) {
  if (v < 0 || v >= vertex_capacity() || !vertex_alive(v)) {
    throw Error("remove_vertex: " + vertex_text(v) + " is not a live vertex");
  }
  for (const Triangle& t : triangles) {
    if (t[0] == v || t[1] == v || t[2] == v) {
      throw Error("remove_vertex: the hole triangulation still uses " + vertex_text(v));
    }
  }
  static thread_local std::vector<int> fan;
  incident_faces(v, fan);
  if (triangles.size() + 2 != fan.size()) {
    throw Error("remove_vertex: a hole of " + std::to_string(fan.size()) + " edges needs " +
                std::to_string(fan.size() - 2) + " triangles");
  }
  replace_faces(fan, triangles);
}

void HalfedgeMesh::validate() const {
  std::vector<int> outgoing(positions_.size(), 0);
  int faces = 0;
  for (int f = 0; f < face_capacity(); ++f) {
    if (!face_alive(f)) continue;
    ++faces;
    for (int c = 0; c < 3; ++c) {
      const int h = 3 * f + c;
      const std::string where = "halfedge " + std::to_string(h);
      if (head_[h] < 0 || head_[h] >= vertex_capacity() || !vertex_alive(head_[h])) {
        throw Error(where + " points to a dead vertex");
      }
      const int t = twin_[h];
      if (t < 0 || t >= 3 * face_capacity() || !face_alive(face_of(t))) {
        throw Error(where + " has no live twin");
      }
      if (twin_[t] != h) throw Error(where + ": twin is not symmetric");
      if (head_[t] != tail(h) || tail(t) != head_[h]) throw Error(where + ": twin reversed wrong");
      if (head_[h] == tail(h)) throw Error(where + " is a loop");
      ++outgoing[tail(h)];
    }
  }
  if (faces != alive_faces_) throw Error("face count out of date");
  int vertices = 0;
  std::vector<int> ring;
  for (int v = 0; v < vertex_capacity(); ++v) {
    if (!vertex_alive(v)) {
      if (outgoing[v] != 0) throw Error(vertex_text(v) + " is removed but still used");
      continue;
    }
    ++vertices;
    const int h0 = out_[v];
    if (h0 < 0 || !face_alive(face_of(h0)) || tail(h0) != v) {
      throw Error(vertex_text(v) + " has an invalid outgoing halfedge");
    }
    int count = 0;
    int h = h0;
    do {
      ++count;
      h = rotate_ccw(h);
    } while (h != h0 && count <= outgoing[v]);
    if (count != outgoing[v]) throw Error(vertex_text(v) + " star is not a single fan");
    if (count < 3) throw Error(vertex_text(v) + " has fewer than 3 neighbours");
    one_ring(v, ring);
    std::sort(ring.begin(), ring.end());
    if (std::adjacent_find(ring.begin(), ring.end()) != ring.end()) {
      throw Error(vertex_text(v) + " has a duplicate edge");
    }
  }
  if (vertices != alive_vertices_) throw Error("vertex count out of date");
}

HalfedgeMesh::Compacted HalfedgeMesh::to_surface_mesh() const {
  Compacted result;
  result.old_to_new.assign(positions_.size(), -1);
  result.new_to_old.reserve(static_cast<std::size_t>(alive_vertices_));
  for (int v = 0; v < vertex_capacity(); ++v) {
    if (!vertex_alive(v)) continue;
    result.old_to_new[v] = static_cast<int>(result.new_to_old.size());
    result.new_to_old.push_back(v);
  }
  SurfaceMesh& mesh = result.mesh;
  mesh.points.reserve(result.new_to_old.size());
  for (int v : result.new_to_old) mesh.points.push_back(positions_[v]);
  if (!vertex_markers_.empty()) {
    for (int v : result.new_to_old) mesh.vertex_markers.push_back(vertex_markers_[v]);
  }
  mesh.triangles.reserve(static_cast<std::size_t>(alive_faces_));
  for (int f = 0; f < face_capacity(); ++f) {
    if (!face_alive(f)) continue;
    const Triangle t = face_vertices(f);
    mesh.triangles.push_back(
        {result.old_to_new[t[0]], result.old_to_new[t[1]], result.old_to_new[t[2]]});
    if (!face_markers_.empty()) mesh.face_markers.push_back(face_markers_[f]);
  }
  return result;
}

}  // namespace molmesh
