// Randomised edit-then-validate test of HalfedgeMesh's mutation gateway: thousands of
// seeded edits (flips, vertex removals, edge collapses, re-triangulated discs, and as many
// edits that must be refused), each checked against an oracle that does not go through
// replace_faces: the mesh the edit should produce, built from scratch by the constructor.
// An edit must succeed exactly when that mesh is a valid closed manifold; a successful one
// must produce exactly it, a refused one must leave every slot of the structure unchanged.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <random>
#include <span>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/processing/halfedge_mesh.hpp"
#include "processing/synthetic_meshes.hpp"

namespace molmesh {
namespace {

// Rotated so the smallest index comes first: the same oriented triangle compares equal.
Triangle canonical(Triangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// Markers on every vertex and face, several faces per marker value, so a refused edit that
// relabels a face (new faces take the first replaced face's marker) shows in the snapshot.
SurfaceMesh with_markers(SurfaceMesh mesh) {
  mesh.vertex_markers.resize(mesh.points.size());
  for (std::size_t v = 0; v < mesh.points.size(); ++v)
    mesh.vertex_markers[v] = 1 + static_cast<int>(v % 5);
  mesh.face_markers.resize(mesh.triangles.size());
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
    mesh.face_markers[f] = 1 + static_cast<int>(f % 7);
  return mesh;
}

// Everything observable about the structure, slot by slot (tombstones included), and its
// compacted form: what a refused edit must leave exactly as it was.
struct State {
  int vertex_capacity = 0, face_capacity = 0, vertex_count = 0, face_count = 0;
  std::vector<Vec3> positions;
  std::vector<int> outgoing, heads, twins;
  std::vector<bool> face_alive;
  SurfaceMesh compact;
};

State state_of(const HalfedgeMesh& mesh) {
  State s;
  s.vertex_capacity = mesh.vertex_capacity();
  s.face_capacity = mesh.face_capacity();
  s.vertex_count = mesh.vertex_count();
  s.face_count = mesh.face_count();
  s.positions = mesh.positions();
  for (int v = 0; v < s.vertex_capacity; ++v) s.outgoing.push_back(mesh.outgoing(v));
  for (int f = 0; f < s.face_capacity; ++f) {
    s.face_alive.push_back(mesh.face_alive(f));
    for (int c = 0; c < 3; ++c) {
      s.heads.push_back(mesh.head(3 * f + c));
      s.twins.push_back(mesh.twin(3 * f + c));
    }
  }
  s.compact = mesh.to_surface_mesh().mesh;
  return s;
}

void expect_same(const State& before, const State& after) {
  EXPECT_EQ(before.vertex_capacity, after.vertex_capacity);
  EXPECT_EQ(before.face_capacity, after.face_capacity);
  EXPECT_EQ(before.vertex_count, after.vertex_count);
  EXPECT_EQ(before.face_count, after.face_count);
  EXPECT_TRUE(before.positions == after.positions);
  EXPECT_EQ(before.outgoing, after.outgoing);
  EXPECT_EQ(before.heads, after.heads);
  EXPECT_EQ(before.twins, after.twins);
  EXPECT_EQ(before.face_alive, after.face_alive);
  EXPECT_TRUE(before.compact.points == after.compact.points);
  EXPECT_EQ(before.compact.triangles, after.compact.triangles);
  EXPECT_EQ(before.compact.vertex_markers, after.compact.vertex_markers);
  EXPECT_EQ(before.compact.face_markers, after.compact.face_markers);
}

// What replace_faces(faces, triangles) should produce: the surviving faces plus the new
// ones (canonical triangle -> face marker), in input vertex numbering; nullopt when that is
// not a closed, oriented, manifold surface with every vertex of valence >= 3, or when a new
// triangle uses a vertex outside the replaced faces (the gateway's contract).
struct Expected {
  std::map<Triangle, int> faces;
  int vertices = 0;
};

std::optional<Expected> expected_result(const HalfedgeMesh& mesh, std::span<const int> faces,
                                        std::span<const Triangle> triangles) {
  std::vector<bool> replaced(mesh.face_capacity(), false), in_region(mesh.vertex_capacity(), false);
  for (int f : faces) {
    if (f < 0 || f >= mesh.face_capacity() || !mesh.face_alive(f)) return std::nullopt;
    replaced[f] = true;
    for (int v : mesh.face_vertices(f)) in_region[v] = true;
  }
  for (const Triangle& t : triangles) {
    for (int v : t) {
      if (v < 0 || v >= mesh.vertex_capacity() || !in_region[v]) return std::nullopt;
    }
  }
  const auto compact = mesh.to_surface_mesh();
  Expected expected;
  SurfaceMesh result;
  result.points = mesh.positions();  // removed vertices stay unused: the constructor drops them
  for (int f = 0; f < mesh.face_capacity(); ++f) {
    if (!mesh.face_alive(f) || replaced[f]) continue;
    result.triangles.push_back(mesh.face_vertices(f));
  }
  // Markers of surviving faces, read back from the compacted mesh (faces in slot order).
  std::vector<int> marker(mesh.face_capacity(), 0);
  for (int f = 0, i = 0; f < mesh.face_capacity(); ++f) {
    if (mesh.face_alive(f)) marker[f] = compact.mesh.face_markers[i++];
  }
  for (int f = 0; f < mesh.face_capacity(); ++f) {
    if (mesh.face_alive(f) && !replaced[f])
      expected.faces[canonical(mesh.face_vertices(f))] = marker[f];
  }
  for (const Triangle& t : triangles) {
    result.triangles.push_back(t);
    expected.faces[canonical(t)] = faces.empty() ? 0 : marker[faces[0]];
  }
  if (expected.faces.size() != result.triangles.size()) return std::nullopt;  // repeated face
  try {
    const HalfedgeMesh built(result);
    built.validate();  // also refuses a vertex of valence < 3 and duplicate edges
    expected.vertices = built.vertex_count();
  } catch (const Error&) {
    return std::nullopt;
  }
  return expected;
}

// A successful edit produced exactly the expected surface (positions and vertex markers of
// the survivors untouched, the expected faces with their markers).
void expect_result(const HalfedgeMesh& mesh, const Expected& expected, const State& before) {
  const auto compact = mesh.to_surface_mesh();
  ASSERT_EQ(mesh.vertex_count(), expected.vertices);
  ASSERT_EQ(compact.mesh.triangles.size(), expected.faces.size());
  std::map<Triangle, int> got;
  for (std::size_t f = 0; f < compact.mesh.triangles.size(); ++f) {
    Triangle t = compact.mesh.triangles[f];
    for (int& v : t) v = compact.new_to_old[v];
    got[canonical(t)] = compact.mesh.face_markers[f];
  }
  EXPECT_EQ(got, expected.faces);
  for (std::size_t i = 0; i < compact.new_to_old.size(); ++i) {
    const int v = compact.new_to_old[i];
    EXPECT_TRUE(compact.mesh.points[i] == before.positions[v]);
    EXPECT_EQ(compact.mesh.vertex_markers[i], 1 + v % 5);
  }
}

TEST(HalfedgeMeshRandomEdits, EveryEditIsValidOrRefusedWithoutATrace) {
  std::mt19937 rng(17);
  auto uniform = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };

  // Vertices are never created, so the mesh shrinks; below this it starts over on the
  // other mesh (an icosphere: valences 5 and 6; a gridded box: 4 to 6, flat faces).
  constexpr int kRestartBelow = 60;
  constexpr int kEdits = 4000;
  int mesh_number = 0;
  auto fresh_mesh = [&] {
    return HalfedgeMesh(with_markers(mesh_number++ % 2 == 0 ? icosphere(Vec3::Zero(), 1.0, 3)
                                                            : test::gridded_box(6, 1.0)));
  };
  HalfedgeMesh mesh = fresh_mesh();

  auto random_live_vertex = [&] {
    for (;;) {
      const int v = uniform(mesh.vertex_capacity());
      if (mesh.vertex_alive(v)) return v;
    }
  };
  auto random_live_face = [&] {
    for (;;) {
      const int f = uniform(mesh.face_capacity());
      if (mesh.face_alive(f)) return f;
    }
  };
  // The hole of v filled as a fan from ring[apex].
  auto fan_fill = [&](const std::vector<int>& ring, int apex) {
    std::vector<Triangle> fill;
    const int m = static_cast<int>(ring.size());
    for (int i = 1; i + 1 < m; ++i) {
      fill.push_back({ring[apex], ring[(apex + i) % m], ring[(apex + i + 1) % m]});
    }
    return fill;
  };

  enum Kind { kFlip, kRemove, kRemoveIllegal, kSameStar, kCollapse, kRandomDisc, kBadFaces };
  std::map<Kind, std::array<int, 2>> tally;  // kind -> {done, refused}
  std::vector<int> ring, faces;
  std::vector<Triangle> triangles;

  for (int step = 0; step < kEdits; ++step) {
    SCOPED_TRACE("edit " + std::to_string(step) + " on mesh " + std::to_string(mesh_number));
    if (mesh.vertex_count() < kRestartBelow) mesh = fresh_mesh();
    faces.clear();
    triangles.clear();
    int removed_vertex = HalfedgeMesh::kInvalid;  // remove_vertex(removed_vertex, triangles)
    int flip = HalfedgeMesh::kInvalid;            // flip_edge(flip)

    const int pick = uniform(100);
    Kind kind;
    if (pick < 35) {
      kind = kFlip;
      flip = 3 * random_live_face() + uniform(3);
      faces = {HalfedgeMesh::face_of(flip), HalfedgeMesh::face_of(mesh.twin(flip))};
      const int a = mesh.tail(flip), b = mesh.head(flip);
      const int c = mesh.head(HalfedgeMesh::next(flip));
      const int d = mesh.head(HalfedgeMesh::next(mesh.twin(flip)));
      triangles = {Triangle{a, d, c}, Triangle{d, b, c}};
    } else if (pick < 50) {
      kind = kRemove;
      removed_vertex = random_live_vertex();
      mesh.one_ring(removed_vertex, ring);
      triangles = fan_fill(ring, uniform(static_cast<int>(ring.size())));
    } else if (pick < 60) {
      kind = kRemoveIllegal;
      removed_vertex = random_live_vertex();
      mesh.one_ring(removed_vertex, ring);
      triangles = fan_fill(ring, 0);
      switch (uniform(5)) {
        case 0:
          triangles.pop_back();
          break;  // one triangle short
        case 1:
          triangles.push_back(triangles.back());
          break;  // one too many
        case 2:
          triangles[0][0] = removed_vertex;
          break;  // still uses v
        case 3:
          std::swap(triangles[0][1], triangles[0][2]);
          break;    // one reversed
        default: {  // a vertex outside the one-ring (never the vertex or its ring)
          const int w = random_live_vertex();
          if (w == removed_vertex || std::count(ring.begin(), ring.end(), w)) continue;
          triangles.back()[1] = w;
        }
      }
    } else if (pick < 65) {
      // The star of v handed back as it is, corners rotated and faces shuffled: a no-op
      // through the whole gateway (slots reused in a different order).
      kind = kSameStar;
      mesh.incident_faces(random_live_vertex(), faces);
      std::shuffle(faces.begin(), faces.end(), rng);
      for (int f : faces) {
        Triangle t = mesh.face_vertices(f);
        std::rotate(t.begin(), t.begin() + uniform(3), t.end());
        triangles.push_back(t);
      }
      std::shuffle(triangles.begin(), triangles.end(), rng);
    } else if (pick < 75) {
      // Edge collapse a -> b: the two stars replaced by b's star over both; refused unless
      // the link condition holds and every valence stays >= 3.
      kind = kCollapse;
      const int h = 3 * random_live_face() + uniform(3);
      const int a = mesh.tail(h), b = mesh.head(h);
      mesh.incident_faces(a, faces);
      mesh.incident_faces(b, ring);
      for (int f : ring) {
        if (std::find(faces.begin(), faces.end(), f) == faces.end()) faces.push_back(f);
      }
      for (int f : faces) {
        Triangle t = mesh.face_vertices(f);
        if (std::count(t.begin(), t.end(), a) && std::count(t.begin(), t.end(), b)) continue;
        for (int& v : t) v = v == a ? b : v;
        triangles.push_back(t);
      }
    } else if (pick < 95) {
      // A small disc (a vertex star, or one face and its neighbours) re-triangulated at
      // random: (almost) always refused.
      kind = kRandomDisc;
      if (uniform(2) == 0) {
        mesh.incident_faces(random_live_vertex(), faces);
      } else {
        const int f = random_live_face();
        faces = {f};
        for (int c = 0; c < 3; ++c) faces.push_back(HalfedgeMesh::face_of(mesh.twin(3 * f + c)));
        std::sort(faces.begin() + 1, faces.end());
        faces.erase(std::unique(faces.begin() + 1, faces.end()), faces.end());
      }
      std::vector<int> region;
      for (int f : faces) {
        for (int v : mesh.face_vertices(f)) region.push_back(v);
      }
      std::sort(region.begin(), region.end());
      region.erase(std::unique(region.begin(), region.end()), region.end());
      const int n = 1 + uniform(static_cast<int>(faces.size()) + 2);
      for (int t = 0; t < n; ++t) {
        std::shuffle(region.begin(), region.end(), rng);
        triangles.push_back({region[0], region[1], region[2]});
      }
    } else {
      kind = kBadFaces;  // a star with one face replaced by a removed or out-of-range one
      mesh.incident_faces(random_live_vertex(), faces);
      for (int f : faces) triangles.push_back(mesh.face_vertices(f));
      switch (uniform(3)) {
        case 0:
          faces.back() = mesh.face_capacity();
          break;
        case 1:
          faces.back() = -1;
          break;
        default: {
          int f = 0;
          while (f < mesh.face_capacity() && mesh.face_alive(f)) ++f;
          if (f == mesh.face_capacity()) continue;  // no tombstone yet
          faces.back() = f;
        }
      }
    }

    // remove_vertex's own refusals (wrong count, v still used) come before the gateway's.
    std::optional<Expected> expected;
    if (removed_vertex != HalfedgeMesh::kInvalid) {
      mesh.incident_faces(removed_vertex, faces);
      const bool uses_v = std::any_of(triangles.begin(), triangles.end(), [&](const Triangle& t) {
        return std::count(t.begin(), t.end(), removed_vertex) > 0;
      });
      if (!uses_v && triangles.size() + 2 == faces.size()) {
        expected = expected_result(mesh, faces, triangles);
      }
    } else {
      expected = expected_result(mesh, faces, triangles);
    }
    if (kind == kFlip) {
      ASSERT_EQ(mesh.can_flip(flip), expected.has_value());
    }
    if (kind == kSameStar) {
      ASSERT_TRUE(expected.has_value());
    }

    const State before = state_of(mesh);
    bool refused = false;
    try {
      if (flip != HalfedgeMesh::kInvalid) {
        mesh.flip_edge(flip);
      } else if (removed_vertex != HalfedgeMesh::kInvalid) {
        mesh.remove_vertex(removed_vertex, triangles);
      } else {
        mesh.replace_faces(faces, triangles);
      }
    } catch (const Error&) {
      refused = true;
    }
    ASSERT_NO_THROW(mesh.validate());
    ASSERT_EQ(refused, !expected.has_value())
        << (refused ? "refused a valid edit" : "accepted an invalid edit");
    ++tally[kind][refused ? 1 : 0];
    if (refused) {
      expect_same(before, state_of(mesh));
    } else {
      expect_result(mesh, *expected, before);
      EXPECT_EQ(mesh.face_count(), before.face_count + static_cast<int>(triangles.size()) -
                                       static_cast<int>(faces.size()));
      if (kind == kFlip || kind == kSameStar) {
        EXPECT_EQ(mesh.vertex_count(), before.vertex_count);
      }
      if (kind == kRemove || kind == kCollapse) {
        EXPECT_EQ(mesh.vertex_count(), before.vertex_count - 1);
        EXPECT_EQ(mesh.face_count(), before.face_count - 2);
      }
    }
    // Still a sphere: V - E + F = 2 with E = 3F/2 on a closed triangle mesh.
    ASSERT_EQ(mesh.face_count() % 2, 0);
    ASSERT_EQ(mesh.vertex_count() - mesh.face_count() / 2, 2);
    if (step % 100 == 0) {
      ASSERT_EQ(test::euler_characteristic(mesh.to_surface_mesh().mesh), 2);
    }
    if (HasFatalFailure() || HasNonfatalFailure()) return;
  }

  // Every kind of edit was done and refused often enough to mean something (the same star
  // is always valid; illegal removals and bad face lists never are).
  for (Kind kind : {kFlip, kRemove, kRemoveIllegal, kSameStar, kCollapse, kRandomDisc, kBadFaces}) {
    const auto [done, refused] = tally[kind];
    SCOPED_TRACE("edit kind " + std::to_string(kind));
    EXPECT_GE(done + refused, 100);
    if (kind == kBadFaces || kind == kRemoveIllegal) {
      EXPECT_EQ(done, 0);
    } else if (kind != kRandomDisc) {  // random triangles: (almost) always refused
      EXPECT_GE(done, 20);
    }
    if (kind != kSameStar) {
      EXPECT_GE(refused, 20);
    }
  }
  EXPECT_GE(mesh_number, 3);  // the shrink-and-restart cycle ran on both meshes
}

}  // namespace
}  // namespace molmesh
