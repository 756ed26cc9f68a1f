#include "molmesh/surface/marching_cubes.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>

#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

// Cube corners: bit 0 = +x, bit 1 = +y, bit 2 = +z.
constexpr int kCorner[8][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
// Edges as (lower corner, upper corner); edge / 4 is the axis.
constexpr int kEdge[12][2] = {{0, 1}, {2, 3}, {4, 5}, {6, 7}, {0, 2}, {1, 3},
                              {4, 6}, {5, 7}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
// Faces with corners counter-clockwise seen from outside the cube.
constexpr int kFace[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};

// Vertices are kept this fraction of a cell away from grid nodes: a sample exactly at the
// isovalue would otherwise put several vertices on one node and create zero-area triangles.
constexpr double kNodeGap = 1e-3;

struct Tables {
  int edge_of[8][8];
  int face_edge[6][4];      // edge between face corner k and k+1
  bool share_face[12][12];  // both edges lie on one face of the cube

  Tables() {
    for (auto& row : edge_of)
      for (int& e : row) e = -1;
    for (int e = 0; e < 12; ++e) {
      edge_of[kEdge[e][0]][kEdge[e][1]] = e;
      edge_of[kEdge[e][1]][kEdge[e][0]] = e;
    }
    for (auto& row : share_face)
      for (bool& s : row) s = false;
    for (int f = 0; f < 6; ++f) {
      for (int k = 0; k < 4; ++k) face_edge[f][k] = edge_of[kFace[f][k]][kFace[f][(k + 1) % 4]];
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) share_face[face_edge[f][a]][face_edge[f][b]] = true;
    }
  }
};

const Tables& tables() {
  static const Tables t;
  return t;
}

// The input grid surrounded by one layer of outside samples (index 0 and n+1 per axis).
struct PaddedField {
  const Grid& grid;
  double isovalue;
  double pad;
  int dims[3];

  PaddedField(const Grid& g, double iso, double pad_value)
      : grid(g), isovalue(iso), pad(pad_value) {
    for (int a = 0; a < 3; ++a) dims[a] = g.dims[a] + 2;
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims[1]) * k);
  }
  bool in_grid(int i, int j, int k) const {
    return i >= 1 && j >= 1 && k >= 1 && i <= grid.dims[0] && j <= grid.dims[1] &&
           k <= grid.dims[2];
  }
  double value(int i, int j, int k) const {
    return in_grid(i, j, k) ? grid.at(i - 1, j - 1, k - 1) : pad;
  }
  Vec3 position(int i, int j, int k) const { return grid.position(i - 1, j - 1, k - 1); }
};

// Quality of a triangle in [0, 1]: 1 equilateral, 0 degenerate.
double triangle_quality(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double l2 = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  if (!(l2 > 0.0)) return 0.0;
  return 2.0 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / l2;
}

struct SlabOutput {
  std::vector<Triangle> triangles;  // negative indices: -(1 + index into extra_points)
  std::vector<Vec3> extra_points;
};

// Triangulates one closed polygon (edge numbers of the cube, in loop order) so that no
// diagonal joins two vertices of one cube face: on a face with four crossings such a chord
// could be chosen by the neighbouring cube too, and the edge would get four triangles.
// Among the admissible triangulations the one with the best worst triangle wins; if none
// exists, a vertex at the centroid closes the polygon.
void triangulate_loop(const int* loop, int n, const int* vertex_of_edge,
                      const std::vector<Vec3>& points, SlabOutput& out) {
  const Tables& t = tables();
  auto vid = [&](int k) { return vertex_of_edge[loop[k]]; };
  // The loops run clockwise seen from outside (towards lower values); emit reversed.
  auto emit = [&](int a, int b, int c) { out.triangles.push_back({a, c, b}); };
  if (n == 3) {
    emit(vid(0), vid(1), vid(2));
    return;
  }
  constexpr int kMax = 12;
  double best[kMax][kMax];
  int split[kMax][kMax];
  auto allowed = [&](int i, int j) {
    return j - i == 1 || (i == 0 && j == n - 1) || !t.share_face[loop[i]][loop[j]];
  };
  for (int i = 0; i + 1 < n; ++i) best[i][i + 1] = 2.0;  // no triangle: neutral
  for (int len = 2; len < n; ++len)
    for (int i = 0; i + len < n; ++i) {
      const int j = i + len;
      best[i][j] = -1.0;
      split[i][j] = -1;
      if (!allowed(i, j)) continue;
      for (int m = i + 1; m < j; ++m) {
        if (best[i][m] < 0.0 || best[m][j] < 0.0) continue;
        const double q =
            std::min({best[i][m], best[m][j],
                      triangle_quality(points[vid(i)], points[vid(m)], points[vid(j)])});
        if (q > best[i][j]) {
          best[i][j] = q;
          split[i][j] = m;
        }
      }
    }
  if (split[0][n - 1] >= 0) {
    int stack[2 * kMax][2];
    int top = 0;
    stack[top][0] = 0;
    stack[top][1] = n - 1;
    ++top;
    while (top > 0) {
      --top;
      const int i = stack[top][0];
      const int j = stack[top][1];
      const int m = split[i][j];
      emit(vid(i), vid(m), vid(j));
      if (m - i >= 2) {
        stack[top][0] = i;
        stack[top][1] = m;
        ++top;
      }
      if (j - m >= 2) {
        stack[top][0] = m;
        stack[top][1] = j;
        ++top;
      }
    }
    return;
  }
  Vec3 centroid = Vec3::Zero();
  for (int k = 0; k < n; ++k) centroid += points[vid(k)];
  out.extra_points.push_back(centroid / n);
  const int c = -static_cast<int>(out.extra_points.size());
  for (int k = 0; k < n; ++k) emit(vid(k), vid((k + 1) % n), c);
}

// Samples >= isovalue are inside (NaN is outside); the padding layer is outside. Also says
// whether any inside sample lies on the grid's own boundary.
std::vector<std::uint8_t> classify_samples(const Grid& grid, const PaddedField& field,
                                           double isovalue, bool& boundary_inside) {
  const int P = field.dims[0], Q = field.dims[1], R = field.dims[2];
  std::vector<std::uint8_t> inside(static_cast<std::size_t>(P) * Q * R, 0);
  tbb::parallel_for(tbb::blocked_range<int>(1, R - 1), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k)
      for (int j = 1; j < Q - 1; ++j)
        for (int i = 1; i < P - 1; ++i)
          inside[field.index(i, j, k)] = grid.at(i - 1, j - 1, k - 1) >= isovalue ? 1 : 0;
  });
  boundary_inside = false;
  for (int k = 1; k < R - 1 && !boundary_inside; ++k)
    for (int j = 1; j < Q - 1 && !boundary_inside; ++j) {
      const bool boundary_row = j == 1 || k == 1 || j == Q - 2 || k == R - 2;
      for (int i = 1; i < P - 1; i = boundary_row || i == P - 2 ? i + 1 : P - 2)
        if (inside[field.index(i, j, k)]) {
          boundary_inside = true;
          break;
        }
    }
  return inside;
}

// Pass 1: one vertex per crossed grid edge, numbered by (plane, row, sample, axis), into
// `points`; edge_vertex[3 * sample + axis] is its number. Left uninitialised elsewhere: only
// entries of crossed edges are written and read, so the pages of empty space are never
// touched.
std::unique_ptr<std::int32_t[]> place_edge_vertices(const PaddedField& field,
                                                    const std::vector<std::uint8_t>& inside,
                                                    double isovalue, std::vector<Vec3>& points) {
  const int P = field.dims[0], Q = field.dims[1], R = field.dims[2];
  const std::size_t plane_size = static_cast<std::size_t>(P) * Q;
  auto edge_vertex = std::make_unique_for_overwrite<std::int32_t[]>(3 * plane_size * R);
  std::vector<std::size_t> plane_count(static_cast<std::size_t>(R) + 1, 0);
  auto crossing = [&](std::size_t s, int axis, int i, int j, int k) {
    const int upper[3] = {i + (axis == 0), j + (axis == 1), k + (axis == 2)};
    if (upper[0] >= P || upper[1] >= Q || upper[2] >= R) return false;
    return inside[s] != inside[field.index(upper[0], upper[1], upper[2])];
  };
  tbb::parallel_for(tbb::blocked_range<int>(0, R), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k) {
      std::size_t count = 0;
      for (int j = 0; j < Q; ++j)
        for (int i = 0; i < P; ++i) {
          const std::size_t s = field.index(i, j, k);
          for (int axis = 0; axis < 3; ++axis) count += crossing(s, axis, i, j, k) ? 1 : 0;
        }
      plane_count[static_cast<std::size_t>(k) + 1] = count;
    }
  });
  for (int k = 0; k < R; ++k) plane_count[k + 1] += plane_count[k];
  const std::size_t edge_vertices = plane_count.back();
  if (edge_vertices > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max() / 2))
    throw Error("the surface would have too many vertices; use a coarser spacing");

  points.resize(edge_vertices);
  tbb::parallel_for(tbb::blocked_range<int>(0, R), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k) {
      std::size_t next = plane_count[k];
      for (int j = 0; j < Q; ++j)
        for (int i = 0; i < P; ++i) {
          const std::size_t s = field.index(i, j, k);
          for (int axis = 0; axis < 3; ++axis) {
            if (!crossing(s, axis, i, j, k)) continue;
            const int i1 = i + (axis == 0), j1 = j + (axis == 1), k1 = k + (axis == 2);
            const double f0 = field.value(i, j, k);
            const double f1 = field.value(i1, j1, k1);
            const bool lower_in = inside[s] != 0;
            const double fin = lower_in ? f0 : f1;
            const double fout = lower_in ? f1 : f0;
            // Fraction of the way from the inside sample to the outside one.
            double u = (fin - isovalue) / (fin - fout);
            if (!std::isfinite(u)) u = 0.5;
            u = std::clamp(u, kNodeGap, 1.0 - kNodeGap);
            const double w = lower_in ? u : 1.0 - u;
            points[next] = (1.0 - w) * field.position(i, j, k) + w * field.position(i1, j1, k1);
            edge_vertex[3 * s + axis] = static_cast<std::int32_t>(next);
            ++next;
          }
        }
    }
  });
  return edge_vertex;
}

// The crossings on each face of a cube (corner mask `mask`, values minus the isovalue `g`)
// joined into segments: next_edge[e] is the edge the surface's loop goes to from edge e
// (-1: e is not crossed). A face's ambiguity is decided by the asymptotic decider, from the
// face's values only, so both cubes sharing it agree.
void join_face_crossings(int mask, const double g[8], int next_edge[12]) {
  const Tables& tab = tables();
  for (int e = 0; e < 12; ++e) next_edge[e] = -1;
  for (int f = 0; f < 6; ++f) {
    const int* fc = kFace[f];
    bool in[4];
    int n_in = 0;
    for (int q = 0; q < 4; ++q) {
      in[q] = (mask >> fc[q]) & 1;
      n_in += in[q];
    }
    if (n_in == 0 || n_in == 4) continue;
    // Crossings walking counter-clockwise: leaving the inside, entering it.
    int leave[2], enter[2], n_leave = 0, n_enter = 0;
    for (int q = 0; q < 4; ++q) {
      const bool a = in[q], b = in[(q + 1) % 4];
      if (a && !b) leave[n_leave++] = q;
      if (!a && b) enter[n_enter++] = q;
    }
    if (n_leave == 1) {
      next_edge[tab.face_edge[f][leave[0]]] = tab.face_edge[f][enter[0]];
      continue;
    }
    // Four crossings: inside corners at q and q+2. The bilinear interpolant's saddle is
    // inside iff g_in0 * g_in2 >= g_out1 * g_out3 (exact products, so both cubes decide
    // identically).
    const int q0 = in[0] ? 0 : 1;
    const bool connect_inside = g[fc[q0]] * g[fc[q0 + 2]] >= g[fc[q0 + 1]] * g[fc[(q0 + 3) % 4]];
    for (int l = 0; l < 2; ++l) {
      const int q = leave[l];  // corner q inside, q+1 outside
      // Connected inside: cut off the outside corner q+1 (leave q -> enter q+1).
      // Separated inside: cut off the inside corner q (leave q -> enter q-1).
      const int target = connect_inside ? (q + 1) % 4 : (q + 3) % 4;
      next_edge[tab.face_edge[f][q]] = tab.face_edge[f][target];
    }
  }
}

// Pass 2 for the cube at (i, j, k): its face segments form closed loops, each triangulated
// into `out`.
void march_cube(const PaddedField& field, const std::vector<std::uint8_t>& inside,
                const std::int32_t* edge_vertex, double isovalue, const std::vector<Vec3>& points,
                int i, int j, int k, SlabOutput& out) {
  int mask = 0;
  for (int c = 0; c < 8; ++c)
    if (inside[field.index(i + kCorner[c][0], j + kCorner[c][1], k + kCorner[c][2])])
      mask |= 1 << c;
  if (mask == 0 || mask == 255) return;
  double g[8];
  for (int c = 0; c < 8; ++c)
    g[c] = field.value(i + kCorner[c][0], j + kCorner[c][1], k + kCorner[c][2]) - isovalue;
  int vertex_of_edge[12];
  for (int e = 0; e < 12; ++e) {
    const int c = kEdge[e][0];
    const std::size_t s = field.index(i + kCorner[c][0], j + kCorner[c][1], k + kCorner[c][2]);
    const bool crossed = ((mask >> kEdge[e][0]) & 1) != ((mask >> kEdge[e][1]) & 1);
    vertex_of_edge[e] = crossed ? edge_vertex[3 * s + e / 4] : -1;
  }
  int next_edge[12];
  join_face_crossings(mask, g, next_edge);
  bool used[12] = {};
  for (int e0 = 0; e0 < 12; ++e0) {
    if (next_edge[e0] < 0 || used[e0]) continue;
    int loop[12];
    int n = 0;
    for (int e = e0; !used[e]; e = next_edge[e]) {
      used[e] = true;
      loop[n++] = e;
    }
    triangulate_loop(loop, n, vertex_of_edge, points, out);
  }
}

// The slabs' triangles and centroid vertices appended to `mesh` in slab order, the centroid
// references (negative) renumbered.
void append_slabs(const std::vector<SlabOutput>& slabs, SurfaceMesh& mesh) {
  std::size_t n_triangles = 0, n_extra = 0;
  for (const SlabOutput& s : slabs) {
    n_triangles += s.triangles.size();
    n_extra += s.extra_points.size();
  }
  mesh.points.reserve(mesh.points.size() + n_extra);
  mesh.triangles.reserve(n_triangles);
  for (const SlabOutput& s : slabs) {
    const int base = static_cast<int>(mesh.points.size());
    mesh.points.insert(mesh.points.end(), s.extra_points.begin(), s.extra_points.end());
    for (Triangle t : s.triangles) {
      for (int& v : t)
        if (v < 0) v = base + (-v - 1);
      mesh.triangles.push_back(t);
    }
  }
}

}  // namespace

SurfaceMesh marching_cubes(const Grid& grid, double isovalue, const Reporter& reporter) {
  if (grid.dims[0] < 1 || grid.dims[1] < 1 || grid.dims[2] < 1 || grid.values.size() != grid.size())
    throw Error("marching cubes needs a non-empty grid whose value count matches its size");
  if (!std::isfinite(isovalue)) throw Error("the isovalue must be a finite number");
  reporter.progress("marching cubes", 0.0);

  // Outside padding: the smallest sample if it is outside, so boundary vertices sit on the
  // grid's own scale; otherwise one unit below the isovalue.
  double lowest = std::numeric_limits<double>::max();
  for (double v : grid.values)
    if (std::isfinite(v)) lowest = std::min(lowest, v);
  const double pad = lowest < isovalue ? lowest : isovalue - 1.0;
  const PaddedField field(grid, isovalue, pad);
  const int P = field.dims[0], Q = field.dims[1], R = field.dims[2];

  bool boundary_inside = false;
  const std::vector<std::uint8_t> inside = classify_samples(grid, field, isovalue, boundary_inside);
  if (boundary_inside)
    reporter.warn(
        "the volume is inside the surface on its boundary; the surface is closed "
        "one cell beyond the grid");

  SurfaceMesh mesh;
  const auto edge_vertex = place_edge_vertices(field, inside, isovalue, mesh.points);
  reporter.progress("marching cubes", 0.3);

  // Pass 2, slab by slab in parallel (each slab's output apart, joined in order).
  const int cube_slabs = R - 1;
  std::vector<SlabOutput> slabs(static_cast<std::size_t>(cube_slabs));
  std::atomic<int> slabs_done{0};
  std::mutex report_mutex;
  tbb::parallel_for(tbb::blocked_range<int>(0, cube_slabs), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k) {
      SlabOutput& out = slabs[static_cast<std::size_t>(k)];
      for (int j = 0; j + 1 < Q; ++j)
        for (int i = 0; i + 1 < P; ++i)
          march_cube(field, inside, edge_vertex.get(), isovalue, mesh.points, i, j, k, out);
      const int done = ++slabs_done;
      std::unique_lock lock(report_mutex, std::try_to_lock);
      if (lock.owns_lock()) reporter.progress("marching cubes", 0.3 + 0.65 * done / cube_slabs);
    }
  });
  append_slabs(slabs, mesh);
  reporter.progress("marching cubes", 1.0);
  return mesh;
}

}  // namespace molmesh
