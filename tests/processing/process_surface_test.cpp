#include "molmesh/processing/process_surface.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>

#include "molmesh/core/error.hpp"
#include "processing/molecule_surfaces.hpp"

namespace molmesh {
namespace {

ProcessingResult run(const SurfaceMesh& raw, int threads, const ProcessingOptions& options = {}) {
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                            static_cast<std::size_t>(threads));
  return process_surface(raw, options);
}

TEST(ProcessSurface, SameBitsWithOneOrTwoThreads) {
  const SurfaceMesh raw = improve_test::raw_surface("1a1p.pqr");
  const ProcessingResult one = run(raw, 1);
  const ProcessingResult two = run(raw, 2);
  ASSERT_EQ(one.mesh.points.size(), two.mesh.points.size());
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
  EXPECT_EQ(one.provenance, two.provenance);
  for (std::size_t v = 0; v < one.mesh.points.size(); ++v) {
    ASSERT_EQ(one.mesh.points[v], two.mesh.points[v]) << "vertex " << v;
  }
}

TEST(ProcessSurface, ProvenancePointsToNearbyDistinctInputVertices) {
  const SurfaceMesh raw = improve_test::raw_surface("1a1p.pqr");
  const ProcessingResult result = process_surface(raw, {});
  ASSERT_EQ(result.provenance.size(), result.mesh.points.size());
  std::vector<int> sorted = result.provenance;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end());
  for (std::size_t v = 0; v < result.provenance.size(); ++v) {
    const int p = result.provenance[v];
    ASSERT_GE(p, 0);
    ASSERT_LT(static_cast<std::size_t>(p), raw.points.size());
    // Relocation slides vertices along the surface by up to about an edge (0.5 Å grid).
    EXPECT_LT((result.mesh.points[v] - raw.points[p]).norm(), 1.5);
  }
  // Stages are recorded in pipeline order.
  ASSERT_GE(result.stages.size(), 5u);
  EXPECT_EQ(result.stages[0].name, "improve");
  EXPECT_EQ(result.stages.back().stats.vertices, result.mesh.points.size());
}

TEST(ProcessSurface, KeepSpheresStayDenseAndTwoThresholdsCoarsenMore) {
  const SurfaceMesh raw = improve_test::raw_surface("1a1p.pqr");
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : raw.points) centre += p;
  centre /= static_cast<double>(raw.points.size());
  // A ball around the surface point nearest the centroid's +x side.
  const auto it = std::max_element(raw.points.begin(), raw.points.end(),
                                   [](const Vec3& a, const Vec3& b) { return a.x() < b.x(); });
  ProcessingOptions options;
  options.keep_spheres.push_back({*it, 4.0});
  const ProcessingResult kept = process_surface(raw, options);
  // The sphere is tested at the vertices' current positions, and relocation slides them
  // by up to ~1 Å before coarsening; every vertex well inside must survive.
  const Sphere core{options.keep_spheres[0].center, options.keep_spheres[0].radius - 1.5};
  std::size_t inside_raw = 0, inside_kept = 0;
  for (const Vec3& p : raw.points) inside_raw += core.contains(p);
  for (int p : kept.provenance) inside_kept += core.contains(raw.points[p]);
  EXPECT_GT(inside_raw, 20u);
  EXPECT_EQ(inside_kept, inside_raw);

  ProcessingOptions twice;
  twice.t0 = {0.2, 0.3};
  const ProcessingResult two = process_surface(raw, twice);
  const ProcessingResult one = process_surface(raw, {});
  EXPECT_LT(two.mesh.points.size(), one.mesh.points.size());
}

TEST(ProcessSurface, RejectsBadOptions) {
  const SurfaceMesh raw = improve_test::raw_surface("1a1p.pqr");
  ProcessingOptions bad;
  bad.rings = 0;
  EXPECT_THROW(process_surface(raw, bad), Error);
  bad = {};
  bad.t0 = {-1.0};
  EXPECT_THROW(process_surface(raw, bad), Error);
}

}  // namespace
}  // namespace molmesh
