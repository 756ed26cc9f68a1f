#include "molmesh/processing/vertex_rings.hpp"

#include <algorithm>

namespace molmesh {

VertexAdjacency vertex_faces(const SurfaceMesh& mesh) {
  VertexAdjacency adjacency;
  const std::size_t n = mesh.points.size();
  adjacency.offsets.assign(n + 1, 0);
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) ++adjacency.offsets[static_cast<std::size_t>(v) + 1];
  }
  for (std::size_t v = 0; v < n; ++v) adjacency.offsets[v + 1] += adjacency.offsets[v];
  adjacency.items.resize(static_cast<std::size_t>(adjacency.offsets[n]));
  std::vector<std::int32_t> fill(adjacency.offsets.begin(), adjacency.offsets.end() - 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    for (int v : mesh.triangles[f]) adjacency.items[fill[v]++] = static_cast<std::int32_t>(f);
  }
  return adjacency;
}

VertexAdjacency ordered_one_rings(const SurfaceMesh& mesh, const VertexAdjacency& faces) {
  const std::size_t n = mesh.points.size();
  VertexAdjacency rings;
  rings.offsets.assign(n + 1, 0);
  // A closed fan has as many neighbours as faces, so the face offsets size the rings; a
  // vertex whose fan does not close gets an empty ring (filled with -1 and compacted).
  std::vector<std::int32_t> items(faces.items.size(), -1);
  std::vector<std::int32_t> next_of;  // per face of the star: the "next" neighbour
  std::vector<std::int32_t> prev_of;
  for (std::size_t v = 0; v < n; ++v) {
    const auto star = faces.of(v);
    const std::size_t m = star.size();
    if (m < 3) continue;
    prev_of.clear();
    next_of.clear();
    for (std::int32_t f : star) {
      const Triangle& t = mesh.triangles[f];
      const int k = t[0] == static_cast<int>(v) ? 0 : (t[1] == static_cast<int>(v) ? 1 : 2);
      prev_of.push_back(t[(k + 1) % 3]);  // (v, a, b): a comes before b around v
      next_of.push_back(t[(k + 2) % 3]);
    }
    // Walk: start at the first face, go from its `a` to `b`, find the face whose `a` is b.
    std::int32_t* out = items.data() + faces.offsets[v];
    std::size_t count = 0;
    std::size_t current = 0;
    bool ok = true;
    for (std::size_t step = 0; step < m; ++step) {
      out[count++] = prev_of[current];
      const std::int32_t target = next_of[current];
      std::size_t found = m;
      for (std::size_t j = 0; j < m; ++j) {
        if (prev_of[j] == target) {
          if (found != m) {
            ok = false;  // two faces continue from the same neighbour: not a disc
            break;
          }
          found = j;
        }
      }
      if (!ok || found == m) {
        ok = false;
        break;
      }
      current = found;
      if (current == 0 && step + 1 < m) {
        ok = false;  // closed early: several fans meet at v (pinched vertex)
        break;
      }
    }
    if (!ok || current != 0) {
      std::fill(out, out + m, -1);
    }
  }
  for (std::size_t v = 0; v < n; ++v) {
    const std::int32_t begin = faces.offsets[v];
    const bool valid = faces.offsets[v + 1] > begin && items[begin] >= 0;
    rings.offsets[v + 1] = rings.offsets[v] + (valid ? faces.offsets[v + 1] - begin : 0);
  }
  rings.items.reserve(static_cast<std::size_t>(rings.offsets[n]));
  for (std::int32_t item : items) {
    if (item >= 0) rings.items.push_back(item);
  }
  return rings;
}

VertexAdjacency vertex_neighbours(const SurfaceMesh& mesh, const VertexAdjacency& faces) {
  const std::size_t n = mesh.points.size();
  VertexAdjacency result;
  result.offsets.assign(n + 1, 0);
  result.items.reserve(faces.items.size());
  std::vector<std::int32_t> local;
  for (std::size_t v = 0; v < n; ++v) {
    local.clear();
    for (std::int32_t f : faces.of(v)) {
      for (int u : mesh.triangles[f]) {
        if (u != static_cast<int>(v)) local.push_back(u);
      }
    }
    std::sort(local.begin(), local.end());
    local.erase(std::unique(local.begin(), local.end()), local.end());
    result.items.insert(result.items.end(), local.begin(), local.end());
    result.offsets[v + 1] = static_cast<std::int32_t>(result.items.size());
  }
  return result;
}

VertexAdjacency k_rings(const SurfaceMesh& mesh, const VertexAdjacency& neighbours, int rings) {
  const std::size_t n = mesh.points.size();
  VertexAdjacency result;
  result.offsets.assign(n + 1, 0);
  result.items.reserve(n * 20);
  std::vector<std::int32_t> mark(n, -1);
  std::vector<std::int32_t> layer;
  std::vector<std::int32_t> next_layer;
  for (std::size_t v = 0; v < n; ++v) {
    const auto vi = static_cast<std::int32_t>(v);
    result.items.push_back(vi);
    mark[v] = vi;
    layer.assign(1, vi);
    for (int r = 0; r < rings && !layer.empty(); ++r) {
      next_layer.clear();
      for (std::int32_t u : layer) {
        for (std::int32_t w : neighbours.of(static_cast<std::size_t>(u))) {
          if (mark[w] != vi) {
            mark[w] = vi;
            next_layer.push_back(w);
          }
        }
      }
      std::sort(next_layer.begin(), next_layer.end());
      result.items.insert(result.items.end(), next_layer.begin(), next_layer.end());
      layer.swap(next_layer);
    }
    result.offsets[v + 1] = static_cast<std::int32_t>(result.items.size());
  }
  return result;
}

}  // namespace molmesh
