#include "molmesh/processing/mesh_repair_steps.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <numeric>
#include <string>
#include <unordered_map>
#include <utility>

#include "molmesh/core/error.hpp"
#include "molmesh/geometry/predicates.hpp"
#include "molmesh/geometry/winding_number.hpp"

namespace molmesh::repair_steps {
namespace {

constexpr std::size_t kMaxExamples = 5;

EdgeKey edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

struct CellHash {
  std::size_t operator()(const std::array<std::int64_t, 3>& c) const {
    // Unsigned arithmetic: the products wrap (defined) instead of overflowing a signed
    // integer for coordinates beyond ~1e7 cells.
    const auto u = [](std::int64_t v) { return static_cast<std::uint64_t>(v); };
    return static_cast<std::size_t>(u(c[0]) * 73856093ull ^ u(c[1]) * 19349663ull ^
                                    u(c[2]) * 83492791ull);
  }
};

// Calls visit(i, j) for each edge, [i, j) being its uses.
template <typename F>
void for_each_edge(const std::vector<EdgeUse>& uses, F&& visit) {
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].key == uses[i].key) ++j;
    visit(i, j);
    i = j;
  }
}

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
      parent[static_cast<std::size_t>(x)] =
          parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
      x = parent[static_cast<std::size_t>(x)];
    }
    return x;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    // The smaller index becomes the root, so roots are deterministic.
    if (a < b) std::swap(a, b);
    parent[static_cast<std::size_t>(a)] = b;
  }
};

int local_index(const Triangle& t, int v) { return t[0] == v ? 0 : t[1] == v ? 1 : 2; }

double area_ratio(const std::vector<Vec3>& p, const Triangle& t) {
  const Vec3& a = p[static_cast<std::size_t>(t[0])];
  const Vec3& b = p[static_cast<std::size_t>(t[1])];
  const Vec3& c = p[static_cast<std::size_t>(t[2])];
  const double longest =
      std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
  if (longest == 0.0) return 0.0;
  return 0.5 * (b - a).cross(c - a).norm() / longest;
}

}  // namespace

std::vector<EdgeUse> edge_uses(const std::vector<Triangle>& tris) {
  std::vector<EdgeUse> uses;
  uses.reserve(3 * tris.size());
  for (std::size_t f = 0; f < tris.size(); ++f) {
    for (int i = 0; i < 3; ++i) {
      uses.push_back({edge_key(tris[f][i], tris[f][(i + 1) % 3]), static_cast<int>(f), i});
    }
  }
  std::sort(uses.begin(), uses.end(), [](const EdgeUse& a, const EdgeUse& b) {
    return a.key != b.key ? a.key < b.key : a.face < b.face;
  });
  return uses;
}

void check_vertex_indices(const SurfaceMesh& input) {
  const auto nv = static_cast<int>(input.points.size());
  for (std::size_t f = 0; f < input.triangles.size(); ++f) {
    for (int v : input.triangles[f]) {
      if (v < 0 || v >= nv) {
        throw Error("triangle " + std::to_string(f + 1) + " refers to vertex " +
                    std::to_string(v + 1) + " but the mesh has " + std::to_string(nv) +
                    " vertices");
      }
    }
  }
}

std::vector<int> merge_map(const std::vector<Vec3>& points, double tol) {
  std::vector<int> rep(points.size());
  std::unordered_map<std::array<std::int64_t, 3>, std::vector<int>, CellHash> cells;
  const double cell = tol > 0.0 ? tol : 1.0;
  for (std::size_t v = 0; v < points.size(); ++v) {
    const Vec3& p = points[v];
    if (!p.allFinite())
      throw Error("vertex " + std::to_string(v + 1) + " has a non-finite coordinate");
    // Clamped so the conversion stays defined for any finite coordinate (a clamped cell
    // only gathers more candidates; closeness is decided by the distance below).
    const auto cell_of = [cell](double x) {
      return static_cast<std::int64_t>(std::clamp(std::floor(x / cell), -1e18, 1e18));
    };
    const std::array<std::int64_t, 3> c{cell_of(p.x()), cell_of(p.y()), cell_of(p.z())};
    int found = -1;
    const int reach = tol > 0.0 ? 1 : 0;
    for (int dz = -reach; dz <= reach; ++dz) {
      for (int dy = -reach; dy <= reach; ++dy) {
        for (int dx = -reach; dx <= reach; ++dx) {
          const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == cells.end()) continue;
          for (int r : it->second) {
            const bool close = tol > 0.0 ? (points[static_cast<std::size_t>(r)] - p).norm() <= tol
                                         : points[static_cast<std::size_t>(r)] == p;
            if (close && (found < 0 || r < found)) found = r;
          }
        }
      }
    }
    if (found >= 0) {
      rep[v] = found;
    } else {
      rep[v] = static_cast<int>(v);
      cells[c].push_back(static_cast<int>(v));
    }
  }
  return rep;
}

std::vector<Triangle> drop_collapsed_and_duplicate_faces(const std::vector<Triangle>& input,
                                                         const std::vector<int>& rep,
                                                         MeshRepairReport& report) {
  std::vector<Triangle> tris;
  tris.reserve(input.size());
  for (const Triangle& t : input) {
    const Triangle m{rep[static_cast<std::size_t>(t[0])], rep[static_cast<std::size_t>(t[1])],
                     rep[static_cast<std::size_t>(t[2])]};
    if (m[0] == m[1] || m[1] == m[2] || m[2] == m[0]) {
      ++report.collapsed_faces;
      continue;
    }
    tris.push_back(m);
  }
  // The first of a set of duplicates stays.
  std::vector<std::pair<Triangle, int>> sorted(tris.size());
  for (std::size_t f = 0; f < tris.size(); ++f) {
    Triangle s = tris[f];
    std::sort(s.begin(), s.end());
    sorted[f] = {s, static_cast<int>(f)};
  }
  std::sort(sorted.begin(), sorted.end());
  std::vector<char> keep(tris.size(), 1);
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    if (sorted[i].first == sorted[i - 1].first)
      keep[static_cast<std::size_t>(sorted[i].second)] = 0;
  }
  std::vector<Triangle> kept;
  kept.reserve(tris.size());
  for (std::size_t f = 0; f < tris.size(); ++f) {
    if (keep[f]) kept.push_back(tris[f]);
  }
  report.duplicate_faces = tris.size() - kept.size();
  return kept;
}

void census_edges(const std::vector<Vec3>& points, const std::vector<Triangle>& tris,
                  const std::vector<EdgeUse>& uses, MeshRepairReport& report) {
  UnionFind loops(points.size());
  std::vector<int> boundary_vertices;
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    const EdgeUse& u = uses[i];
    const Triangle& t = tris[static_cast<std::size_t>(u.face)];
    const int a = t[u.corner];
    const int b = t[(u.corner + 1) % 3];
    const Vec3 mid =
        0.5 * (points[static_cast<std::size_t>(a)] + points[static_cast<std::size_t>(b)]);
    if (j - i > 2) {
      ++report.non_manifold_edges;
      if (report.non_manifold_edge_examples.size() < kMaxExamples) {
        report.non_manifold_edge_examples.push_back(mid);
      }
    } else if (j - i == 1) {
      ++report.boundary_edges;
      loops.unite(a, b);
      boundary_vertices.push_back(a);
      boundary_vertices.push_back(b);
    }
  });
  std::sort(boundary_vertices.begin(), boundary_vertices.end());
  boundary_vertices.erase(std::unique(boundary_vertices.begin(), boundary_vertices.end()),
                          boundary_vertices.end());
  for (int v : boundary_vertices) {
    if (loops.find(v) == v) {
      ++report.holes;
      if (report.hole_examples.size() < kMaxExamples) {
        report.hole_examples.push_back(points[static_cast<std::size_t>(v)]);
      }
    }
  }
}

bool split_pinched_vertices(std::vector<Vec3>& points, std::vector<Triangle>& tris,
                            const std::vector<EdgeUse>& uses, MeshRepairReport& report) {
  UnionFind corners(3 * tris.size());
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i != 2) return;
    const int f = uses[i].face;
    const int g = uses[i + 1].face;
    const Triangle& tf = tris[static_cast<std::size_t>(f)];
    const Triangle& tg = tris[static_cast<std::size_t>(g)];
    for (int v : {tf[uses[i].corner], tf[(uses[i].corner + 1) % 3]}) {
      corners.unite(3 * f + local_index(tf, v), 3 * g + local_index(tg, v));
    }
  });
  std::vector<int> first_root(points.size(), -1);
  std::unordered_map<int, int> copy_of_root;
  const std::size_t split_before = report.split_vertices;
  for (std::size_t c = 0; c < 3 * tris.size(); ++c) {
    const int v = tris[c / 3][c % 3];
    const int root = corners.find(static_cast<int>(c));
    int& first = first_root[static_cast<std::size_t>(v)];
    if (first < 0) first = root;
    if (root == first) continue;
    auto [it, inserted] = copy_of_root.try_emplace(root, static_cast<int>(points.size()));
    if (inserted) {
      points.push_back(points[static_cast<std::size_t>(v)]);
      ++report.split_vertices;
    }
    tris[c / 3][c % 3] = it->second;
  }
  return report.split_vertices > split_before;
}

std::vector<std::vector<int>> orient_components(const std::vector<Vec3>& points,
                                                std::vector<Triangle>& tris,
                                                const std::vector<EdgeUse>& uses,
                                                MeshRepairReport& report) {
  std::vector<std::array<int, 3>> neighbour(tris.size(), {-1, -1, -1});
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i != 2) return;
    neighbour[static_cast<std::size_t>(uses[i].face)][uses[i].corner] = uses[i + 1].face;
    neighbour[static_cast<std::size_t>(uses[i + 1].face)][uses[i + 1].corner] = uses[i].face;
  });
  std::vector<int> component(tris.size(), -1);
  std::vector<char> flip(tris.size(), 0);
  std::vector<std::vector<int>> component_faces;
  std::vector<char> component_orientable;
  for (std::size_t seed = 0; seed < tris.size(); ++seed) {
    if (component[seed] >= 0) continue;
    const int id = static_cast<int>(component_faces.size());
    component_faces.emplace_back();
    component_orientable.push_back(1);
    std::deque<int> queue{static_cast<int>(seed)};
    component[seed] = id;
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop_front();
      component_faces.back().push_back(f);
      const Triangle& tf = tris[static_cast<std::size_t>(f)];
      for (int i = 0; i < 3; ++i) {
        const int g = neighbour[static_cast<std::size_t>(f)][i];
        if (g < 0) continue;
        // Same direction along the shared edge means opposite orientations.
        const Triangle& tg = tris[static_cast<std::size_t>(g)];
        const int a = tf[i];
        const int b = tf[(i + 1) % 3];
        const bool same =
            (tg[0] == a && tg[1] == b) || (tg[1] == a && tg[2] == b) || (tg[2] == a && tg[0] == b);
        const char want = static_cast<char>(flip[static_cast<std::size_t>(f)] ^ (same ? 1 : 0));
        if (component[static_cast<std::size_t>(g)] < 0) {
          component[static_cast<std::size_t>(g)] = id;
          flip[static_cast<std::size_t>(g)] = want;
          queue.push_back(g);
        } else if (flip[static_cast<std::size_t>(g)] != want) {
          component_orientable.back() = 0;
        }
      }
    }
    if (!component_orientable.back()) {
      ++report.non_orientable_components;
      if (report.non_orientable_examples.size() < kMaxExamples) {
        report.non_orientable_examples.push_back(points[static_cast<std::size_t>(tris[seed][0])]);
      }
    }
  }
  report.components = component_faces.size();
  // Within a component, follow the majority so the fewest faces change.
  for (const std::vector<int>& faces : component_faces) {
    std::size_t flipped = 0;
    for (int f : faces) flipped += flip[static_cast<std::size_t>(f)];
    const bool invert = 2 * flipped > faces.size();
    for (int f : faces) {
      if (static_cast<bool>(flip[static_cast<std::size_t>(f)]) != invert) {
        std::swap(tris[static_cast<std::size_t>(f)][1], tris[static_cast<std::size_t>(f)][2]);
        ++report.reoriented_faces;
      }
    }
  }
  return component_faces;
}

void flip_zero_area_caps(const std::vector<Vec3>& points, std::vector<Triangle>& tris,
                         const std::vector<EdgeUse>& uses, double degenerate_ratio,
                         MeshRepairReport& report) {
  std::unordered_map<EdgeKey, std::array<int, 2>> faces_of;
  faces_of.reserve(3 * tris.size() / 2);
  for_each_edge(uses, [&](std::size_t i, std::size_t j) {
    if (j - i == 2) faces_of[uses[i].key] = {uses[i].face, uses[i + 1].face};
  });
  auto replace_face = [&](int a, int b, int from, int to) {
    auto it = faces_of.find(edge_key(a, b));
    if (it == faces_of.end()) return;
    for (int& f : it->second) {
      if (f == from) f = to;
    }
  };
  std::deque<int> pending;
  for (std::size_t f = 0; f < tris.size(); ++f) {
    if (area_ratio(points, tris[f]) <= degenerate_ratio) pending.push_back(static_cast<int>(f));
  }
  std::size_t budget = 4 * pending.size() + 16;
  std::vector<char> stuck(tris.size(), 0);
  while (!pending.empty() && budget-- > 0) {
    const int f = pending.front();
    pending.pop_front();
    Triangle& tf = tris[static_cast<std::size_t>(f)];
    if (area_ratio(points, tf) > degenerate_ratio) continue;
    // Longest edge a->b, opposite corner c.
    int k = 0;
    double best = -1.0;
    for (int i = 0; i < 3; ++i) {
      const double len = (points[static_cast<std::size_t>(tf[(i + 1) % 3])] -
                          points[static_cast<std::size_t>(tf[i])])
                             .squaredNorm();
      if (len > best) {
        best = len;
        k = i;
      }
    }
    const int a = tf[k], b = tf[(k + 1) % 3], c = tf[(k + 2) % 3];
    auto it = faces_of.find(edge_key(a, b));
    if (it == faces_of.end()) {
      stuck[static_cast<std::size_t>(f)] = 1;
      continue;
    }
    const int g = it->second[0] == f ? it->second[1] : it->second[0];
    Triangle& tg = tris[static_cast<std::size_t>(g)];
    const int x = tg[0] + tg[1] + tg[2] - a - b;
    if (x == c || faces_of.count(edge_key(c, x))) {
      stuck[static_cast<std::size_t>(f)] = 1;
      continue;
    }
    const Triangle nf{c, a, x};
    const Triangle ng{c, x, b};
    // Only when the flip leaves both new triangles with positive area on the same side.
    if (area_ratio(points, nf) <= degenerate_ratio && area_ratio(points, ng) <= degenerate_ratio) {
      stuck[static_cast<std::size_t>(f)] = 1;
      continue;
    }
    faces_of.erase(it);
    replace_face(a, x, g, f);
    replace_face(b, c, f, g);
    faces_of[edge_key(c, x)] = {f, g};
    tf = nf;
    tg = ng;
    stuck[static_cast<std::size_t>(f)] = 0;
    ++report.flipped_cap_faces;
    if (area_ratio(points, nf) <= degenerate_ratio) pending.push_back(f);
    if (area_ratio(points, ng) <= degenerate_ratio) pending.push_back(g);
  }
  for (const Triangle& t : tris) {
    report.remaining_degenerate_faces += area_ratio(points, t) <= degenerate_ratio;
  }
}

void orient_outward(const std::vector<Vec3>& points, std::vector<Triangle>& tris,
                    const std::vector<std::vector<int>>& component_faces,
                    MeshRepairReport& report) {
  const std::size_t nc = component_faces.size();
  std::vector<double> volume(nc, 0.0);
  std::vector<Vec3> lo(nc, Vec3::Constant(1e300)), hi(nc, Vec3::Constant(-1e300));
  for (std::size_t c = 0; c < nc; ++c) {
    for (int f : component_faces[c]) {
      const Triangle& t = tris[static_cast<std::size_t>(f)];
      const Vec3& p0 = points[static_cast<std::size_t>(t[0])];
      const Vec3& p1 = points[static_cast<std::size_t>(t[1])];
      const Vec3& p2 = points[static_cast<std::size_t>(t[2])];
      volume[c] += signed_volume(Vec3::Zero(), p0, p1, p2);
      for (const Vec3* p : {&p0, &p1, &p2}) {
        lo[c] = lo[c].cwiseMin(*p);
        hi[c] = hi[c].cwiseMax(*p);
      }
    }
  }
  for (std::size_t c = 0; c < nc; ++c) {
    const Triangle& t0 = tris[static_cast<std::size_t>(component_faces[c].front())];
    const Vec3 q =
        (points[static_cast<std::size_t>(t0[0])] + points[static_cast<std::size_t>(t0[1])] +
         points[static_cast<std::size_t>(t0[2])]) /
        3.0;
    int depth = 0;
    for (std::size_t d = 0; d < nc; ++d) {
      if (d == c || (q.array() < lo[d].array()).any() || (q.array() > hi[d].array()).any())
        continue;
      if (std::abs(winding_number(points, tris, component_faces[d], q)) > 0.5) ++depth;
    }
    const bool want_positive = depth % 2 == 0;
    if ((volume[c] > 0.0) != want_positive) {
      for (int f : component_faces[c]) {
        std::swap(tris[static_cast<std::size_t>(f)][1], tris[static_cast<std::size_t>(f)][2]);
      }
      ++report.reoriented_components;
    }
  }
}

SurfaceMesh compact(const std::vector<Vec3>& points, const std::vector<Triangle>& tris,
                    MeshRepairReport& report) {
  SurfaceMesh out;
  std::vector<int> index(points.size(), -1);
  for (const Triangle& t : tris) {
    for (int v : t) index[static_cast<std::size_t>(v)] = 0;
  }
  for (std::size_t v = 0; v < points.size(); ++v) {
    if (index[v] == 0) {
      index[v] = static_cast<int>(out.points.size());
      out.points.push_back(points[v]);
    }
  }
  // Input vertices that were neither merged away nor kept were unused from the start.
  report.unreferenced_vertices = points.size() - out.points.size() - report.merged_vertices;
  out.triangles.reserve(tris.size());
  for (const Triangle& t : tris) {
    out.triangles.push_back({index[static_cast<std::size_t>(t[0])],
                             index[static_cast<std::size_t>(t[1])],
                             index[static_cast<std::size_t>(t[2])]});
  }
  return out;
}

}  // namespace molmesh::repair_steps
