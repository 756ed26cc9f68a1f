// Repair of user meshes: a real molecular surface (1a1p through marching cubes) is damaged
// in the ways exporters and other tools damage meshes, and repair must undo exactly that,
// or refuse with counts and locations when the damage cannot be undone.
#include "molmesh/processing/mesh_repair.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/gaussian_blur.hpp"
#include "support/structured_meshes.hpp"

namespace molmesh {
namespace {

const SurfaceMesh& molecule() {
  static const SurfaceMesh mesh = [] {
    const Atoms atoms = read_atoms(MOLMESH_TEST_DATA_DIR "/1a1p.pqr");
    return marching_cubes(blur_atoms(atoms, BlurOptions{}), 1.0);
  }();
  return mesh;
}

SurfaceMesh repair(const SurfaceMesh& m, MeshRepairReport& report, bool require = true) {
  MeshRepairOptions options;
  options.require_closed_manifold = require;
  return repair_surface_mesh(m, options, report);
}

void expect_clean(const SurfaceMesh& m, double volume, double relative = 1e-9) {
  const SurfaceStats s = compute_surface_stats(m);
  EXPECT_TRUE(s.closed);
  EXPECT_TRUE(s.manifold);
  EXPECT_NEAR(s.volume, volume, relative * std::abs(volume));
}

TEST(MeshRepair, CleanMeshIsLeftAlone) {
  const SurfaceMesh& m = molecule();
  const SurfaceStats before = compute_surface_stats(m);
  ASSERT_TRUE(before.closed && before.manifold);
  ASSERT_GT(before.volume, 0.0);
  MeshRepairReport report;
  const SurfaceMesh out = repair(m, report);
  EXPECT_EQ(report.repairs(), "nothing to repair");
  EXPECT_EQ(out.points.size(), m.points.size());
  EXPECT_EQ(out.triangles, m.triangles);
}

TEST(MeshRepair, TriangleSoupIsWeldedBack) {
  // What STL (and many PLY exporters) write: three private corners per triangle, with
  // round-off in the coordinates.
  const SurfaceMesh& m = molecule();
  SurfaceMesh soup;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-1e-6, 1e-6);
  for (const Triangle& t : m.triangles) {
    Triangle s;
    for (int c = 0; c < 3; ++c) {
      s[c] = static_cast<int>(soup.points.size());
      soup.points.push_back(m.points[t[c]] + Vec3(jitter(rng), jitter(rng), jitter(rng)));
    }
    soup.triangles.push_back(s);
  }
  MeshRepairReport report;
  const SurfaceMesh out = repair(soup, report);
  EXPECT_EQ(out.points.size(), m.points.size());
  EXPECT_EQ(out.triangles.size(), m.triangles.size());
  EXPECT_EQ(report.merged_vertices, soup.points.size() - m.points.size());
  // The kept corners carry their 1e-6 Å jitter.
  expect_clean(out, compute_surface_stats(m).volume, 1e-6);
}

TEST(MeshRepair, InconsistentAndInvertedOrientationIsFixed) {
  const SurfaceMesh& m = molecule();
  const double volume = compute_surface_stats(m).volume;
  SurfaceMesh bad = m;
  // Invert everything, then re-flip a random third: neither majority nor sign is right.
  std::mt19937 rng(5);
  std::size_t scrambled = 0;
  for (Triangle& t : bad.triangles) {
    std::swap(t[1], t[2]);
    if (rng() % 3 == 0) {
      std::swap(t[1], t[2]);
      ++scrambled;
    }
  }
  ASSERT_GT(scrambled, 100u);
  MeshRepairReport report;
  const SurfaceMesh out = repair(bad, report);
  EXPECT_EQ(report.reoriented_faces, scrambled);
  EXPECT_EQ(report.reoriented_components, 1u);
  expect_clean(out, volume);
}

TEST(MeshRepair, DuplicateAndCollapsedTrianglesAreDropped) {
  const SurfaceMesh& m = molecule();
  SurfaceMesh bad = m;
  for (int i = 0; i < 7; ++i)
    bad.triangles.push_back(m.triangles[static_cast<std::size_t>(50 * i)]);
  Triangle reversed = m.triangles[3];
  std::swap(reversed[0], reversed[1]);
  bad.triangles.push_back(reversed);
  bad.triangles.push_back({4, 4, 9});
  bad.triangles.push_back({10, 11, 10});
  bad.points.push_back(Vec3(1e3, 0.0, 0.0));  // unused
  MeshRepairReport report;
  const SurfaceMesh out = repair(bad, report);
  EXPECT_EQ(report.duplicate_faces, 8u);
  EXPECT_EQ(report.collapsed_faces, 2u);
  EXPECT_EQ(report.unreferenced_vertices, 1u);
  EXPECT_EQ(out.triangles.size(), m.triangles.size());
  expect_clean(out, compute_surface_stats(m).volume);
}

TEST(MeshRepair, ZeroAreaCapIsFlippedAway) {
  // Split edge (a, b) at its midpoint c on one side only and close the slit with the cap
  // (b, a, c): still closed and manifold, but with a zero-area triangle.
  SurfaceMesh m = molecule();
  const double volume = compute_surface_stats(m).volume;
  const Triangle first = m.triangles[0];
  const int a = first[0], b = first[1];
  std::size_t other = 0;
  for (std::size_t f = 1; f < m.triangles.size(); ++f) {
    const Triangle& t = m.triangles[f];
    for (int i = 0; i < 3; ++i) {
      if (t[i] == b && t[(i + 1) % 3] == a) other = f;
    }
  }
  ASSERT_GT(other, 0u);
  const Triangle t = m.triangles[other];
  const int y = t[0] + t[1] + t[2] - a - b;
  const int c = static_cast<int>(m.points.size());
  m.points.push_back(0.5 * (m.points[a] + m.points[b]));
  m.triangles[other] = {b, c, y};
  m.triangles.push_back({c, a, y});
  m.triangles.push_back({b, a, c});
  MeshRepairReport report;
  const SurfaceMesh out = repair(m, report);
  EXPECT_EQ(report.flipped_cap_faces, 1u);
  EXPECT_EQ(report.remaining_degenerate_faces, 0u);
  expect_clean(out, volume);
  const SurfaceStats s = compute_surface_stats(out);
  EXPECT_GT(s.min_angle_deg, 0.0);
  EXPECT_LT(s.max_angle_deg, 180.0);
}

TEST(MeshRepair, HolesAreCountedLocatedAndRefused) {
  SurfaceMesh m = molecule();
  // Three holes far apart: remove one triangle at each.
  const std::size_t n = m.triangles.size();
  const std::vector<std::size_t> removed{n / 5, n / 2, 4 * n / 5};
  for (auto it = removed.rbegin(); it != removed.rend(); ++it) {
    m.triangles.erase(m.triangles.begin() + static_cast<long>(*it));
  }
  MeshRepairReport report;
  try {
    repair(m, report);
    FAIL() << "an open mesh was accepted";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("3 holes (9 edges used by only one triangle)"), std::string::npos) << what;
  }
  EXPECT_EQ(report.holes, 3u);
  EXPECT_EQ(report.boundary_edges, 9u);
  ASSERT_EQ(report.hole_examples.size(), 3u);
  // Each example point is a corner of one of the removed triangles.
  for (const Vec3& p : report.hole_examples) {
    double nearest = 1e300;
    for (std::size_t f : removed) {
      for (int v : molecule().triangles[f])
        nearest = std::min(nearest, (molecule().points[v] - p).norm());
    }
    EXPECT_LT(nearest, 1e-12);
  }
  // Without the requirement the mesh comes back, still open.
  EXPECT_NO_THROW(repair(m, report, false));
  EXPECT_FALSE(report.closed_manifold());
}

TEST(MeshRepair, NonManifoldEdgeIsReported) {
  SurfaceMesh m = molecule();
  // A fin: a third triangle on an existing edge, closed into a tetrahedron-like flap whose
  // other edges are boundary edges.
  const Triangle t = m.triangles[100];
  const int tip = static_cast<int>(m.points.size());
  m.points.push_back(m.points[t[0]] + Vec3(0.0, 0.0, 5.0));
  m.triangles.push_back({t[0], t[1], tip});
  MeshRepairReport report;
  EXPECT_THROW(repair(m, report), Error);
  EXPECT_EQ(report.non_manifold_edges, 1u);
  ASSERT_EQ(report.non_manifold_edge_examples.size(), 1u);
  EXPECT_LT((report.non_manifold_edge_examples[0] - 0.5 * (m.points[t[0]] + m.points[t[1]])).norm(),
            1e-12);
  EXPECT_NE(report.problems().find("1 non-manifold edges"), std::string::npos);
}

TEST(MeshRepair, CavityWallFacesIntoTheCavity) {
  // A hollow box: the inner wall must bound the solid, so its normals point into the hole.
  SurfaceMesh outer = testing::structured_cube_surface(4, 0.0, 1.0);
  const SurfaceMesh inner = testing::structured_cube_surface(2, 0.3, 0.7);
  const double outer_volume = 1.0;
  const double inner_volume = 0.4 * 0.4 * 0.4;
  testing::append_surface(outer, inner);
  MeshRepairReport report;
  const SurfaceMesh out = repair(outer, report);
  EXPECT_EQ(report.components, 2u);
  EXPECT_EQ(report.reoriented_components, 1u);
  expect_clean(out, outer_volume - inner_volume);
}

TEST(MeshRepair, PinchedVertexIsSplit) {
  // Two boxes touching at one corner: after welding, that corner joins two separate fans.
  SurfaceMesh a = testing::structured_cube_surface(1, 0.0, 1.0);
  const SurfaceMesh b = testing::structured_cube_surface(1, 1.0, 2.0);
  testing::append_surface(a, b);
  MeshRepairReport report;
  const SurfaceMesh out = repair(a, report);
  EXPECT_EQ(report.merged_vertices, 1u);
  EXPECT_EQ(report.split_vertices, 1u);
  EXPECT_EQ(report.components, 2u);
  expect_clean(out, 2.0);
}

TEST(MeshRepair, RejectsIndicesOutOfRange) {
  SurfaceMesh m;
  m.points = {Vec3::Zero(), Vec3::UnitX(), Vec3::UnitY()};
  m.triangles = {{0, 1, 3}};
  MeshRepairReport report;
  EXPECT_THROW(repair(m, report), Error);
}

}  // namespace
}  // namespace molmesh
