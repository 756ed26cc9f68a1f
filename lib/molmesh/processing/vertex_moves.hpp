#pragma once
// Shared machinery of the steps that only move vertices (angle improvement, normal-based
// smoothing): a deterministic parallel schedule, and the test that a proposed move keeps
// the vertex star valid (no flipped, folded or degenerate triangle).
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/processing/vertex_rings.hpp"
#include "molmesh/surface/surface_mesh.hpp"

namespace molmesh {

// Greedy colouring in vertex order: no two neighbours share a colour. Vertices of one
// colour can move in parallel in place (each move reads only its neighbours), which gives
// Gauss–Seidel convergence with results independent of the thread count.
std::vector<std::vector<std::int32_t>> colour_classes(const VertexAdjacency& neighbours);

// Angle quality of a triangle in degrees: min(smallest angle, (180° - largest angle) / 2).
// Equals the smallest angle unless the triangle is obtuse beyond 180 - 2·min; 60 for an
// equilateral triangle. Penalises both needles and flat (caps) triangles.
double triangle_quality_deg(const Vec3& a, const Vec3& b, const Vec3& c);
// The cosine of that quality (smaller is better), computed without inverse trigonometry.
double triangle_quality_cos(const Vec3& a, const Vec3& b, const Vec3& c);
// Cosines of a triangle's smallest and largest angles, clamped to [-1, 1] (both 1 for a
// degenerate triangle, which then has the worst quality).
struct AngleCosines {
  double smallest = -1.0;  // the largest cosine: of the smallest angle
  double largest = 1.0;    // the smallest cosine: of the largest angle
};
AngleCosines triangle_angle_cosines(const Vec3& a, const Vec3& b, const Vec3& c);

// Worst quality over the fan (x, ring[i], ring[i+1]).
double star_quality_deg(const Vec3& x, std::span<const std::int32_t> ring,
                        const std::vector<Vec3>& points);
double star_quality_cos(const Vec3& x, std::span<const std::int32_t> ring,
                        const std::vector<Vec3>& points);

struct MoveLimits {
  double max_normal_turn_deg = 30.0;  // no incident triangle's normal turns more than this
  double min_area_ratio = 0.02;       // nor shrinks below this fraction of its old area
  int max_halvings = 4;               // halve a rejected move this many times, then refuse
  bool require_quality = true;        // the star's worst quality may not decrease
};

// Tries x -> target, then halfway points; returns the accepted position, or nothing.
std::optional<Vec3> accept_move(const Vec3& x, const Vec3& target,
                                std::span<const std::int32_t> ring, const std::vector<Vec3>& points,
                                const MoveLimits& limits);

// Runs move(v) for every vertex with a valid ordered ring, colour by colour (in parallel
// within a colour) and writes the accepted positions in place. Returns how many moved.
std::size_t sweep_vertices(std::vector<Vec3>& points, const VertexAdjacency& rings,
                           const std::vector<std::vector<std::int32_t>>& colours,
                           const std::function<std::optional<Vec3>(std::size_t)>& move);

}  // namespace molmesh
