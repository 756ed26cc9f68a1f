#include "molmesh/processing/untangle.hpp"

#include <unordered_set>

#include "molmesh/processing/self_intersection.hpp"

namespace molmesh {

std::size_t untangle(SurfaceMesh& mesh, const SurfaceMesh& input,
                     const std::vector<int>& provenance) {
  constexpr int kRounds = 8;
  for (int round = 0;; ++round) {
    const auto crossings = self_intersections(mesh);
    if (crossings.empty() || round == kRounds) return crossings.size();
    // Halfway first (keeps most of the quality gain), all the way back in later rounds.
    const double back = round < kRounds / 2 ? 0.5 : 1.0;
    std::unordered_set<int> moved;
    for (const auto& [a, b] : crossings)
      for (int t : {a, b})
        for (int v : mesh.triangles[static_cast<std::size_t>(t)]) {
          if (!moved.insert(v).second) continue;
          const int from = provenance[static_cast<std::size_t>(v)];
          Vec3& p = mesh.points[static_cast<std::size_t>(v)];
          p += back * (input.points[static_cast<std::size_t>(from)] - p);
        }
  }
}

}  // namespace molmesh
