#include "molmesh/processing/coarsen.hpp"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <span>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/geometry/predicates.hpp"
#include "molmesh/geometry/sphere_union.hpp"
#include "molmesh/processing/edge_flips.hpp"
#include "molmesh/processing/halfedge_mesh.hpp"
#include "molmesh/processing/structure_tensor.hpp"

namespace molmesh {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Larger holes are left alone: they only occur at badly shaped vertices that quality
// improvement should fix first, and the O(M^3) triangulation search stays bounded.
constexpr int kMaxHoleValence = 24;
// New triangles may tilt at most this far from the removed fan's mean normal.
const double kCosMaxTilt = std::cos(60.0 * std::numbers::pi / 180.0);
// Triangles thinner than this are degenerate for our purposes.
const double kMinTriangleAngle = 1.0 * std::numbers::pi / 180.0;
// Radians of minimum angle traded per unit of (height of x above a new triangle) / (hole
// radius); see plan_removal.
constexpr double kFidelityWeight = 2.0;

// Angle-weighted unit vertex normal, as vertex_normals.hpp defines it, computed on the
// editable mesh so that passes need no conversion to a plain mesh.
Vec3 vertex_normal(const HalfedgeMesh& mesh, int v) {
  Vec3 sum = Vec3::Zero();
  const Vec3& x = mesh.position(v);
  const int h0 = mesh.outgoing(v);
  int h = h0;
  do {
    const Vec3 e1 = mesh.position(mesh.head(h)) - x;
    const Vec3 e2 = mesh.position(mesh.head(HalfedgeMesh::next(h))) - x;
    const Vec3 n = e1.cross(e2);
    const double len = n.norm();
    if (len > 0) sum += std::atan2(len, e1.dot(e2)) * (n / len);
    h = mesh.rotate_ccw(h);
  } while (h != h0);
  const double len = sum.norm();
  return len > 0 ? Vec3(sum / len) : Vec3::Zero();
}

struct Scratch {
  RingScratch rings;
  std::vector<int> verts;
  std::vector<Vec3> normals;
  // hole planning
  std::vector<int> ring, fan, around, valence;
  std::vector<Vec3> p3;
  std::vector<Eigen::Vector2d> p2;
  std::vector<std::uint8_t> edge;  // k*k: ring vertices i, j already adjacent
  std::vector<double> best_min, best_sum;
  std::vector<int> choice;
  std::vector<Triangle> local;  // chosen triangles in ring indices
};

// The hole's polygon seen along the removed fan's mean normal.
struct HolePlane {
  Vec3 normal;
  Vec3 x;            // the vertex being removed
  double scale = 0;  // largest squared distance from x to a ring vertex
  double hole_radius = 0;
};

// Fills s.p3 and s.p2 (ring positions, and their projections on the tangent plane) and
// `plane`; false when the fan has no normal or the ring is not star-shaped around x.
bool project_ring(const HalfedgeMesh& mesh, int v, Scratch& s, HolePlane& plane) {
  const int k = static_cast<int>(s.ring.size());
  Vec3 normal = Vec3::Zero();
  for (int f : s.fan) normal += mesh.face_area_vector(f);
  const double normal_len = normal.norm();
  if (!(normal_len > 0)) return false;
  normal /= normal_len;
  const Vec3 t1 = normal.unitOrthogonal();
  const Vec3 t2 = normal.cross(t1);
  const Vec3& x = mesh.position(v);
  s.p3.resize(k);
  s.p2.resize(k);
  double scale = 0;
  for (int i = 0; i < k; ++i) {
    s.p3[i] = mesh.position(s.ring[i]);
    const Vec3 d = s.p3[i] - x;
    s.p2[i] = {d.dot(t1), d.dot(t2)};
    scale = std::max(scale, d.squaredNorm());
  }
  // The projected ring must wind once, positively, around x (star-shaped polygon);
  // otherwise the vertex sits in a fold and the projection cannot guide the filling.
  double winding = 0;
  for (int i = 0; i < k; ++i) {
    const Eigen::Vector2d& a = s.p2[i];
    const Eigen::Vector2d& b = s.p2[(i + 1) % k];
    const double cross = a.x() * b.y() - a.y() * b.x();
    if (!(cross > 1e-12 * scale)) return false;
    winding += std::atan2(cross, a.dot(b));
  }
  if (std::abs(winding - 2 * std::numbers::pi) > 1e-6) return false;
  const double hole_radius = std::sqrt(scale);
  plane = {normal, x, scale, hole_radius};
  return true;
}

// s.valence: each ring vertex's valence; s.edge: which ring vertices are already adjacent.
void record_ring_edges(const HalfedgeMesh& mesh, Scratch& s) {
  const int k = static_cast<int>(s.ring.size());
  s.valence.resize(k);
  s.edge.assign(static_cast<std::size_t>(k * k), 0);
  for (int i = 0; i < k; ++i) {
    const int r = s.ring[i];
    int count = 0;
    const int h0 = mesh.outgoing(r);
    int h = h0;
    do {
      ++count;
      const int w = mesh.head(h);
      for (int j = 0; j < k; ++j) {
        if (s.ring[j] == w) s.edge[i * k + j] = 1;
      }
      h = mesh.rotate_ccw(h);
    } while (h != h0);
    s.valence[i] = count;
  }
}

// The max-min triangulation of the ring polygon (plan_removal's conditions 1-4) into out, in
// mesh vertices; false when none exists.
bool triangulate_hole(const HolePlane& plane, Scratch& s, std::vector<Triangle>& out) {
  const int k = static_cast<int>(s.ring.size());
  const Vec3& normal = plane.normal;
  const Vec3& x = plane.x;
  const double scale = plane.scale;
  const double hole_radius = plane.hole_radius;
  auto is_polygon_side = [&](int a, int b) { return b - a == 1 || (a == 0 && b == k - 1); };
  auto score = [&](int i, int m, int j) {
    // Diagonals must be new edges.
    if (!is_polygon_side(i, m) && s.edge[i * k + m]) return -1.0;
    if (!is_polygon_side(m, j) && s.edge[m * k + j]) return -1.0;
    if (!is_polygon_side(i, j) && s.edge[i * k + j]) return -1.0;
    // An ear at a ring vertex gives it no new edge; it loses the edge to v.
    int ear = -1;
    if (m == i + 1 && j == m + 1) ear = m;
    if (i == 0 && m == 1 && j == k - 1) ear = 0;
    if (i == 0 && m == k - 2 && j == k - 1) ear = k - 1;
    if (ear >= 0 && s.valence[ear] <= 3) return -1.0;
    const Eigen::Vector2d& a = s.p2[i];
    const Eigen::Vector2d& b = s.p2[m];
    const Eigen::Vector2d& c = s.p2[j];
    const double area2 = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
    if (!(area2 > 1e-9 * scale)) return -1.0;
    const Vec3 n = (s.p3[m] - s.p3[i]).cross(s.p3[j] - s.p3[i]);
    if (n.dot(normal) < kCosMaxTilt * n.norm()) return -1.0;
    const double angle = triangle_min_angle(s.p3[i], s.p3[m], s.p3[j]);
    if (angle < kMinTriangleAngle) return -1.0;
    // Shape fidelity: the height of x above the new triangle's plane, relative to the hole
    // size. Zero for a flat hole and for a straight ridge filled along the ridge line; large
    // when a triangle cuts across a ridge or valley. Weighted so that cutting a 90° edge
    // costs ~45° of minimum angle, while the near-uniform sagitta of a smooth region barely
    // changes the choice.
    const double height = std::abs(n.normalized().dot(x - s.p3[i]));
    double quality = angle - kFidelityWeight * height / hole_radius;
    // A ring vertex left with 3 neighbours cannot get good angles later; accept it only
    // when nothing better exists.
    if (ear >= 0 && s.valence[ear] == 4) quality -= 0.25;
    return std::max(quality, 1e-6);
  };

  // Max-min triangulation of the convex-indexed polygon 0..k-1 by dynamic programming.
  s.best_min.assign(static_cast<std::size_t>(k * k), -1.0);
  s.best_sum.assign(static_cast<std::size_t>(k * k), 0.0);
  s.choice.assign(static_cast<std::size_t>(k * k), -1);
  for (int i = 0; i + 1 < k; ++i) s.best_min[i * k + i + 1] = kInf;
  for (int len = 2; len < k; ++len) {
    for (int i = 0; i + len < k; ++i) {
      const int j = i + len;
      double best = -1.0, best_sum = 0.0;
      int best_m = -1;
      for (int m = i + 1; m < j; ++m) {
        const double left = s.best_min[i * k + m];
        const double right = s.best_min[m * k + j];
        if (left <= 0 || right <= 0) continue;
        const double sc = score(i, m, j);
        if (sc <= 0) continue;
        const double worst = std::min({sc, left, right});
        const double sum = sc + s.best_sum[i * k + m] + s.best_sum[m * k + j];
        if (worst > best + 1e-12 || (worst > best - 1e-12 && sum > best_sum)) {
          best = worst;
          best_sum = sum;
          best_m = m;
        }
      }
      s.best_min[i * k + j] = best;
      s.best_sum[i * k + j] = best_sum;
      s.choice[i * k + j] = best_m;
    }
  }
  if (s.best_min[k - 1] <= 0) return false;

  s.local.clear();
  // Unwind the choices with an explicit stack of (i, j) sub-polygons.
  s.around.clear();
  s.around.push_back(0);
  s.around.push_back(k - 1);
  while (!s.around.empty()) {
    const int j = s.around.back();
    s.around.pop_back();
    const int i = s.around.back();
    s.around.pop_back();
    if (j - i < 2) continue;
    const int m = s.choice[i * k + j];
    s.local.push_back({i, m, j});
    s.around.push_back(i);
    s.around.push_back(m);
    s.around.push_back(m);
    s.around.push_back(j);
  }
  for (const Triangle& t : s.local) out.push_back({s.ring[t[0]], s.ring[t[1]], s.ring[t[2]]});
  return true;
}

// Whether the new triangles `out` cross no face of the ring of faces around the hole and do
// not fold onto their outer neighbours.
bool filling_fits(const HalfedgeMesh& mesh, Scratch& s, const std::vector<Triangle>& out) {
  s.around.clear();
  for (int r : s.ring) {
    const int h0 = mesh.outgoing(r);
    int h = h0;
    do {
      const int f = HalfedgeMesh::face_of(h);
      if (std::find(s.fan.begin(), s.fan.end(), f) == s.fan.end()) s.around.push_back(f);
      h = mesh.rotate_ccw(h);
    } while (h != h0);
  }
  std::sort(s.around.begin(), s.around.end());
  s.around.erase(std::unique(s.around.begin(), s.around.end()), s.around.end());
  for (const Triangle& t : out) {
    Vec3 lo = mesh.position(t[0]).cwiseMin(mesh.position(t[1])).cwiseMin(mesh.position(t[2]));
    Vec3 hi = mesh.position(t[0]).cwiseMax(mesh.position(t[1])).cwiseMax(mesh.position(t[2]));
    const Vec3 n = (mesh.position(t[1]) - mesh.position(t[0]))
                       .cross(mesh.position(t[2]) - mesh.position(t[0]))
                       .normalized();
    for (int f : s.around) {
      const Triangle other = mesh.face_vertices(f);
      int shared = 0;
      for (int a : t) shared += (a == other[0] || a == other[1] || a == other[2]) ? 1 : 0;
      if (shared == 3) return false;
      if (shared == 2) {
        // Across a hole side: the new triangle must not fold onto its outer neighbour
        // beyond a 120° bend, unless the removed fan face was already bent that far.
        const Vec3 m = mesh.face_area_vector(f).normalized();
        if (n.dot(m) < -0.5) {
          // Find the fan face on the same side for the "already that sharp" exception.
          double old_dot = 1.0;
          for (int g : s.fan) {
            const Triangle ft = mesh.face_vertices(g);
            int common = 0;
            for (int a : ft) common += (a == other[0] || a == other[1] || a == other[2]) ? 1 : 0;
            if (common == 2) old_dot = mesh.face_area_vector(g).normalized().dot(m);
          }
          if (n.dot(m) < old_dot) return false;
        }
        continue;
      }
      const Vec3& a = mesh.position(other[0]);
      const Vec3& b = mesh.position(other[1]);
      const Vec3& c = mesh.position(other[2]);
      if ((a.cwiseMax(b).cwiseMax(c).array() < lo.array()).any() ||
          (a.cwiseMin(b).cwiseMin(c).array() > hi.array()).any()) {
        continue;
      }
      if (triangles_intersect(mesh.positions(), t, other, SegmentContact::kProperCrossing))
        return false;
    }
  }
  return true;
}

// Chooses how to fill the hole left by deleting v, or returns false if no safe filling
// exists. Read-only on the mesh. The triangulation maximises the smallest angle (ties: the
// larger sum of minimum angles) over all triangulations of the ring polygon whose
// triangles are (1) not degenerate, (2) positively oriented when projected on the fan's
// tangent plane and tilted by at most 60° from it (no fold-over), (3) free of edges that
// already exist elsewhere, and (4) leave every ring vertex at least 3 neighbours. The
// chosen triangles must then not cross any face of the surrounding ring of faces, nor
// fold onto their outer neighbours.
bool plan_removal(const HalfedgeMesh& mesh, int v, Scratch& s, std::vector<Triangle>& out) {
  out.clear();
  mesh.one_ring(v, s.ring);
  mesh.incident_faces(v, s.fan);
  const int k = static_cast<int>(s.ring.size());
  if (k < 3 || k > kMaxHoleValence) return false;
  HolePlane plane;
  if (!project_ring(mesh, v, s, plane)) return false;
  record_ring_edges(mesh, s);
  if (!triangulate_hole(plane, s, out)) return false;
  return filling_fits(mesh, s, out);
}

void check_options(const CoarsenOptions& options) {
  if (!std::isfinite(options.t0) || !std::isfinite(options.alpha) || !std::isfinite(options.beta)) {
    throw Error("coarsening: t0, alpha and beta must be finite numbers");
  }
  if (options.rings < 1) {
    throw Error("coarsening: rings must be at least 1 (got " + std::to_string(options.rings) + ")");
  }
  if (options.max_passes < 0) throw Error("coarsening: max_passes must not be negative");
  for (const Sphere& sphere : options.keep_spheres) {
    if (!(sphere.radius >= 0) || !sphere.center.allFinite()) {
      throw Error("coarsening: keep-sphere radii must be >= 0 and centres finite");
    }
  }
}

// Step 1: 1 for every vertex inside a keep sphere (never deleted, never flipped around).
std::vector<std::uint8_t> lock_kept_vertices(const HalfedgeMesh& mesh,
                                             std::span<const Sphere> keep_spheres) {
  const int n = mesh.vertex_capacity();
  std::vector<std::uint8_t> locked(static_cast<std::size_t>(n), 0);
  if (!keep_spheres.empty()) {
    tbb::parallel_for(0, n, [&](int v) { locked[v] = in_any(keep_spheres, mesh.position(v)); });
  }
  return locked;
}

// Step 2: connected components, so that none is reduced below a tetrahedron.
struct Components {
  std::vector<int> of_vertex;  // component id per vertex, -1 for dead vertices
  std::vector<int> size;       // live vertices per component
};

Components connected_components(const HalfedgeMesh& mesh) {
  const int n = mesh.vertex_capacity();
  Components c;
  c.of_vertex.assign(static_cast<std::size_t>(n), -1);
  std::vector<int> stack;
  for (int v = 0; v < n; ++v) {
    if (!mesh.vertex_alive(v) || c.of_vertex[v] >= 0) continue;
    const int id = static_cast<int>(c.size.size());
    c.size.push_back(0);
    c.of_vertex[v] = id;
    stack.push_back(v);
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      ++c.size[id];
      const int h0 = mesh.outgoing(u);
      int h = h0;
      do {
        const int w = mesh.head(h);
        if (c.of_vertex[w] < 0) {
          c.of_vertex[w] = id;
          stack.push_back(w);
        }
        h = mesh.rotate_ccw(h);
      } while (h != h0);
    }
  }
  return c;
}

// Step 3 of a pass: the live vertices of `changed` and every vertex within `rings` edges of
// them, each once (stamp[v] == pass marks the ones taken).
void collect_dirty(const HalfedgeMesh& mesh, const std::vector<int>& changed, int rings, int pass,
                   std::vector<int>& stamp, std::vector<int>& dirty) {
  dirty.clear();
  for (int v : changed) {
    if (mesh.vertex_alive(v) && stamp[v] != pass) {
      stamp[v] = pass;
      dirty.push_back(v);
    }
  }
  std::size_t begin = 0;
  for (int r = 0; r < rings; ++r) {
    const std::size_t end = dirty.size();
    for (std::size_t i = begin; i < end; ++i) {
      const int u = dirty[i];
      const int h0 = mesh.outgoing(u);
      int h = h0;
      do {
        const int w = mesh.head(h);
        if (stamp[w] != pass) {
          stamp[w] = pass;
          dirty.push_back(w);
        }
        h = mesh.rotate_ccw(h);
      } while (h != h0);
    }
    begin = end;
  }
}

// Step 4: Eq. 6 at every dirty vertex, in parallel; infinity where the vertex is locked or
// its structure tensor is degenerate.
void evaluate_eq6(const HalfedgeMesh& mesh, const std::vector<int>& dirty,
                  const std::vector<Vec3>& normals, const std::vector<std::uint8_t>& locked,
                  const CoarsenOptions& options, tbb::enumerable_thread_specific<Scratch>& scratch,
                  std::vector<double>& value) {
  const bool plain_exponents = options.alpha == 1.0 && options.beta == 1.0;
  tbb::parallel_for(std::size_t{0}, dirty.size(), [&](std::size_t i) {
    const int v = dirty[i];
    value[v] = kInf;
    if (locked[v]) return;
    Scratch& s = scratch.local();
    const Vec3& x = mesh.position(v);
    double longest = 0;
    const int h0 = mesh.outgoing(v);
    int h = h0;
    do {
      longest = std::max(longest, (mesh.position(mesh.head(h)) - x).squaredNorm());
      h = mesh.rotate_ccw(h);
    } while (h != h0);
    longest = std::sqrt(longest);
    mesh.k_ring(v, options.rings, s.rings, s.verts);
    s.normals.clear();
    for (int u : s.verts) s.normals.push_back(normals[u]);
    const StructureTensor tensor = structure_tensor_of_normals(s.normals);
    if (!(tensor.eigenvalues[0] > 0)) return;
    const double ratio = tensor.eigenvalues[1] / tensor.eigenvalues[0];
    value[v] = plain_exponents ? longest * ratio
                               : std::pow(longest, options.alpha) * std::pow(ratio, options.beta);
  });
}

// Step 5: of the candidates (sorted most deletable first), those whose stars no earlier one
// touches (blocked[v] == pass marks a taken star).
void select_disjoint_stars(const HalfedgeMesh& mesh, const std::vector<int>& candidates, int pass,
                           std::vector<int>& blocked, std::vector<int>& selected) {
  selected.clear();
  for (int v : candidates) {
    if (blocked[v] == pass) continue;
    selected.push_back(v);
    blocked[v] = pass;
    const int h0 = mesh.outgoing(v);
    int h = h0;
    do {
      blocked[mesh.head(h)] = pass;
      h = mesh.rotate_ccw(h);
    } while (h != h0);
  }
}

// Step 6: colour the selection so that two vertices of one colour share no ring vertex:
// their holes, the faces around the holes, and the edges a filling may create are then
// disjoint, so a colour class is planned in parallel on the current mesh and applied in
// priority order with exactly the outcome of a sequential run, whatever the thread count.
void colour_selection(const HalfedgeMesh& mesh, const std::vector<int>& selected,
                      std::vector<std::uint64_t>& color_mask,
                      std::vector<std::vector<int>>& classes, std::vector<int>& ring) {
  color_mask.assign(static_cast<std::size_t>(mesh.vertex_capacity()), 0);
  for (auto& members : classes) members.clear();
  for (int v : selected) {
    mesh.one_ring(v, ring);
    std::uint64_t used = 0;
    for (int r : ring) used |= color_mask[r];
    if (~used == 0) continue;  // 64 colours taken around v: leave it to the next pass
    const int color = std::countr_zero(~used);
    for (int r : ring) color_mask[r] |= std::uint64_t{1} << color;
    if (static_cast<int>(classes.size()) <= color) classes.resize(color + 1);
    classes[color].push_back(v);
  }
}

// Step 7: plan the removals of one colour class in parallel, then apply them in order.
// Returns how many were removed; their fillings' vertices go to `changed`.
std::size_t remove_class(HalfedgeMesh& mesh, const std::vector<int>& members,
                         Components& components, tbb::enumerable_thread_specific<Scratch>& scratch,
                         std::vector<std::vector<Triangle>>& plans,
                         std::vector<std::uint8_t>& planned, std::vector<double>& value,
                         std::vector<int>& changed) {
  plans.resize(std::max(plans.size(), members.size()));
  planned.assign(members.size(), 0);
  tbb::parallel_for(std::size_t{0}, members.size(), [&](std::size_t i) {
    planned[i] = plan_removal(mesh, members[i], scratch.local(), plans[i]) ? 1 : 0;
  });
  std::size_t removed = 0;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const int v = members[i];
    int& component_size = components.size[components.of_vertex[v]];
    if (!planned[i] || component_size <= 4) continue;
    try {
      mesh.remove_vertex(v, plans[i]);
    } catch (const Error&) {
      continue;  // the gateway refused (cannot happen for a valid plan): keep v
    }
    value[v] = kInf;
    for (const Triangle& t : plans[i]) changed.insert(changed.end(), t.begin(), t.end());
    --component_size;
    ++removed;
  }
  return removed;
}

}  // namespace

CoarsenResult coarsen(const SurfaceMesh& input, const CoarsenOptions& options,
                      const Reporter& reporter) {
  check_options(options);
  HalfedgeMesh mesh(input);
  const int n = mesh.vertex_capacity();
  const int initial_vertices = mesh.vertex_count();
  const std::vector<std::uint8_t> locked = lock_kept_vertices(mesh, options.keep_spheres);
  Components components = connected_components(mesh);

  tbb::enumerable_thread_specific<Scratch> scratch;
  std::vector<int> ring;
  std::vector<Vec3> normals(static_cast<std::size_t>(n), Vec3::Zero());
  std::vector<double> value(static_cast<std::size_t>(n), kInf);
  std::vector<int> candidates, selected, blocked(static_cast<std::size_t>(n), -1);
  std::vector<std::uint64_t> color_mask;
  std::vector<std::vector<int>> classes;
  std::vector<std::vector<Triangle>> plans;
  std::vector<std::uint8_t> planned;

  CoarsenResult result;
  // Only stars around deleted vertices change, so after the first pass the normals are
  // refreshed at the ring vertices of deleted ones (`changed`) and Eq. 6 re-evaluated
  // within `rings` edges of them (`dirty`); elsewhere last pass's value still holds.
  std::vector<int> changed, dirty;
  std::vector<int> stamp(static_cast<std::size_t>(n), -1);
  for (int v = 0; v < n; ++v) {
    if (mesh.vertex_alive(v)) changed.push_back(v);
  }
  for (int pass = 0; pass < options.max_passes && options.t0 > 0; ++pass) {
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    tbb::parallel_for(std::size_t{0}, changed.size(), [&](std::size_t i) {
      const int v = changed[i];
      if (mesh.vertex_alive(v)) normals[v] = vertex_normal(mesh, v);
    });
    if (pass == 0) {
      dirty = changed;
    } else {
      collect_dirty(mesh, changed, options.rings, pass, stamp, dirty);
    }
    evaluate_eq6(mesh, dirty, normals, locked, options, scratch, value);
    changed.clear();

    candidates.clear();
    for (int v = 0; v < n; ++v) {
      if (value[v] < options.t0) candidates.push_back(v);
    }
    if (candidates.empty()) break;
    // Most deletable first (flattest and densest), index as the tie-break: deterministic.
    std::sort(candidates.begin(), candidates.end(),
              [&](int a, int b) { return value[a] < value[b] || (value[a] == value[b] && a < b); });
    select_disjoint_stars(mesh, candidates, pass, blocked, selected);
    colour_selection(mesh, selected, color_mask, classes, ring);
    // Classes run in colour order, each seeing the previous ones' edits.
    std::size_t removed_this_pass = 0;
    for (const std::vector<int>& members : classes) {
      removed_this_pass +=
          remove_class(mesh, members, components, scratch, plans, planned, value, changed);
    }
    result.removed += removed_this_pass;
    result.passes = pass + 1;
    reporter.progress("coarsen", static_cast<double>(pass + 1) / options.max_passes);
    if (removed_this_pass == 0) break;
  }

  if (options.equalize_valence && result.removed > 0) {
    flip_edges_for_valence(mesh, FlipOptions{}, 30.0, locked);
  }
  reporter.progress("coarsen", 1.0);

  HalfedgeMesh::Compacted compact = mesh.to_surface_mesh();
  result.mesh = std::move(compact.mesh);
  result.provenance = std::move(compact.new_to_old);
  result.removed = static_cast<std::size_t>(initial_vertices - mesh.vertex_count());
  return result;
}

}  // namespace molmesh
