// TetGen never takes the process down (issue 18): its input is validated first (closed,
// manifold, no near-duplicate vertices, no self-intersection, sane option values), and an
// error TetGen raises itself becomes a molmesh::Error instead of a crash.
#include <gtest/gtest.h>
#include <tetgen.h>

#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "molmesh/tetmesh/tetgen_plc.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace molmesh {
namespace {

std::string error_of(const SurfaceMesh& s, const TetMeshOptions& o = {}) {
  try {
    tetrahedralize(s, {}, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TetMeshOptions interior() {
  TetMeshOptions o;
  o.domain = Domain::interior;
  return o;
}

// Appends an axis-aligned box [lo, hi] (outward triangles) to `s`.
void add_box(SurfaceMesh& s, const Vec3& lo, const Vec3& hi) {
  const int base = static_cast<int>(s.points.size());
  for (int k = 0; k < 8; ++k)
    s.points.push_back(
        Vec3(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z()));
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    s.triangles.push_back({base + q[0], base + q[1], base + q[2]});
    s.triangles.push_back({base + q[0], base + q[2], base + q[3]});
  }
}

TEST(TetgenInput, ValidBoxMeshes) {
  SurfaceMesh box;
  add_box(box, Vec3(0, 0, 0), Vec3(1, 1, 1));
  EXPECT_EQ(error_of(box, interior()), "");
}

TEST(TetgenInput, NonManifoldEdgeIsRefused) {
  // Two boxes sharing one edge: that edge has four triangles.
  SurfaceMesh s;
  add_box(s, Vec3(0, 0, 0), Vec3(1, 1, 1));
  add_box(s, Vec3(1, 1, 0), Vec3(2, 2, 1));
  // Weld the shared edge (x = y = 1) of the second box onto the first's vertices.
  for (auto& t : s.triangles)
    for (int& v : t) {
      if (v == 8)
        v = 3;  // (1,1,0)
      else if (v == 12)
        v = 7;  // (1,1,1)
    }
  EXPECT_NE(error_of(s, interior()).find("manifold"), std::string::npos) << error_of(s, interior());
}

TEST(TetgenInput, NearDuplicateVerticesAreRefused) {
  SurfaceMesh s;
  add_box(s, Vec3(0, 0, 0), Vec3(1, 1, 1));
  add_box(s, Vec3(1 + 1e-13, 0, 0), Vec3(2, 1, 1));  // touches the first within 1e-13
  EXPECT_NE(error_of(s, interior()).find("coincide"), std::string::npos) << error_of(s, interior());
}

TEST(TetgenInput, SelfIntersectionIsRefused) {
  SurfaceMesh s;
  add_box(s, Vec3(0, 0, 0), Vec3(1, 1, 1));
  add_box(s, Vec3(0.5, 0.5, 0.5), Vec3(1.5, 1.5, 1.5));
  EXPECT_NE(error_of(s, interior()).find("intersects itself"), std::string::npos)
      << error_of(s, interior());
}

TEST(TetgenInput, ErrorsTetgenRaisesAreExceptionsNotCrashes) {
  // TetGen itself on a PLC that tetrahedralize() would refuse (two boxes cutting through
  // each other): TetGen throws its error code 3. Before tetgen_terminate.cpp its cleanup
  // double-freed while unwinding and the process died with SIGSEGV.
  SurfaceMesh s;
  add_box(s, Vec3(0, 0, 0), Vec3(1, 1, 1));
  add_box(s, Vec3(0.5, 0.5, 0.5), Vec3(1.5, 1.5, 1.5));
  tetgenio in;
  detail::fill_plc(s, SurfaceMesh{}, {}, in);
  tetgenio out;
  tetgenbehavior behavior;
  std::string switches = "pYzQ";
  ASSERT_TRUE(behavior.parse_commandline(switches.data()));
  int code = 0;
  try {
    ::tetrahedralize(&behavior, &in, &out, nullptr, nullptr);
  } catch (int thrown) {
    code = thrown;
  }
  EXPECT_NE(code, 0);
}

TEST(TetgenInput, OptionValuesAreRangeChecked) {
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 1);
  const double nan = std::nan("");
  auto with = [](auto change) {
    TetMeshOptions o;
    change(o);
    return o;
  };
  for (const TetMeshOptions& o : {with([](TetMeshOptions& o) { o.outer_radius = 1e300; }),
                                  with([&](TetMeshOptions& o) { o.outer_radius = nan; }),
                                  with([&](TetMeshOptions& o) { o.min_dihedral_deg = nan; }),
                                  with([&](TetMeshOptions& o) { o.max_radius_edge_ratio = nan; }),
                                  with([&](TetMeshOptions& o) { o.sphere_ratio = INFINITY; }),
                                  with([&](TetMeshOptions& o) { o.size_factor = nan; }),
                                  with([&](TetMeshOptions& o) { o.surface_size_ratio = 0.0; }),
                                  with([&](TetMeshOptions& o) { o.surface_size_ratio = nan; }),
                                  with([&](TetMeshOptions& o) { o.max_volume = -1.0; })}) {
    EXPECT_THROW(o.validate(), Error);
    EXPECT_THROW(tetrahedralize(ion, {}, o), Error);
  }
  EXPECT_NO_THROW(TetMeshOptions{}.validate());
}

TEST(TetgenInput, TinySizeFactorIsRefusedByTheMemoryEstimate) {
  // --size-factor 1e-3 on an 86-vertex surface ran for minutes; now refused at once.
  const SurfaceMesh ion = icosphere(Vec3::Zero(), 3.0, 2);
  TetMeshOptions o = interior();
  o.size_factor = 1e-3;
  const std::string message = error_of(ion, o);
  EXPECT_NE(message.find("`max_memory_bytes`"), std::string::npos) << message;
  EXPECT_NE(message.find("`size_factor`"), std::string::npos) << message;
  EXPECT_EQ(message.find("--"), std::string::npos) << message;  // no CLI flag in the library
}

}  // namespace
}  // namespace molmesh
