#include "molmesh/processing/untangle.hpp"

#include <algorithm>
#include <unordered_set>

#include "molmesh/processing/self_intersection.hpp"

namespace molmesh {
namespace {

// The vertices of the triangles of `crossings`, sorted.
std::vector<int> crossing_vertices(const SurfaceMesh& mesh,
                                   const std::vector<std::pair<int, int>>& crossings) {
  std::vector<int> vertices;
  for (const auto& [a, b] : crossings)
    for (int t : {a, b})
      for (int v : mesh.triangles[static_cast<std::size_t>(t)]) vertices.push_back(v);
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

// Each vertex's neighbours along edges, sorted (so sums over them do not depend on the
// triangle order).
std::vector<std::vector<int>> vertex_neighbours(const SurfaceMesh& mesh) {
  std::vector<std::vector<int>> neighbours(mesh.points.size());
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c)
      for (int d = 1; d < 3; ++d)
        neighbours[static_cast<std::size_t>(t[c])].push_back(t[(c + d) % 3]);
  for (auto& n : neighbours) {
    std::sort(n.begin(), n.end());
    n.erase(std::unique(n.begin(), n.end()), n.end());
  }
  return neighbours;
}

}  // namespace

std::size_t untangle(SurfaceMesh& mesh, const SurfaceMesh& input,
                     const std::vector<int>& provenance) {
  constexpr int kRounds = 8;
  auto crossings = self_intersections(mesh);
  for (int round = 0; round < kRounds && !crossings.empty(); ++round) {
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
    crossings = self_intersections(mesh);
  }
  if (crossings.empty()) return 0;
  // Crossings left with every vertex back where it came from are folds of the new
  // connectivity, not of the positions: coarsening and flips joined input vertices into
  // triangles that overlap where the surface is nearly flat (a valence-3 vertex outside its
  // three neighbours' triangle, vdW creases of fas2's coarse levels). Moving the vertices of
  // the crossing triangles to the mean of their neighbours unfolds such fans.
  const std::vector<std::vector<int>> neighbours = vertex_neighbours(mesh);
  for (int round = 0; round < kRounds && !crossings.empty(); ++round) {
    const std::vector<int> vertices = crossing_vertices(mesh, crossings);
    std::vector<Vec3> centres(vertices.size(), Vec3::Zero());
    for (std::size_t n = 0; n < vertices.size(); ++n) {
      const auto& ring = neighbours[static_cast<std::size_t>(vertices[n])];
      for (int w : ring) centres[n] += mesh.points[static_cast<std::size_t>(w)];
      if (!ring.empty()) centres[n] /= static_cast<double>(ring.size());
    }
    for (std::size_t n = 0; n < vertices.size(); ++n)
      if (!neighbours[static_cast<std::size_t>(vertices[n])].empty())
        mesh.points[static_cast<std::size_t>(vertices[n])] = centres[n];
    crossings = self_intersections(mesh);
  }
  return crossings.size();
}

}  // namespace molmesh
