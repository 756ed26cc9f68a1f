#pragma once
// Checks shared by the coarsening tests (coarsen_test, coarsen_slow_test).
#include <gtest/gtest.h>

#include <cstddef>
#include <vector>

#include "molmesh/processing/coarsen.hpp"

namespace molmesh::test {

// Coarsening never moves a vertex, and deletes none inside `keep`: every output vertex is
// its provenance's input vertex, and every input vertex in the sphere has an output vertex.
// Returns the number of input vertices in the sphere (so a test can ask for enough).
inline std::size_t expect_keep_sphere_untouched(const SurfaceMesh& input,
                                                const CoarsenResult& result, const Sphere& keep) {
  std::vector<char> present(input.points.size(), 0);
  for (std::size_t i = 0; i < result.provenance.size(); ++i) {
    present[result.provenance[i]] = 1;
    EXPECT_EQ(result.mesh.points[i], input.points[result.provenance[i]]);
  }
  std::size_t inside = 0;
  for (std::size_t v = 0; v < input.points.size(); ++v) {
    if (!keep.contains(input.points[v])) continue;
    ++inside;
    EXPECT_TRUE(present[v]) << "vertex " << v << " inside the keep-sphere was deleted";
  }
  return inside;
}

}  // namespace molmesh::test
