#pragma once
// Collapse of the triangles that relocation and flips cannot repair. A triangle with a
// tiny edge on a crease (an SES re-entrant crease, a vdW seam between two atoms) cannot be
// flipped away: its neighbours across the crease bend by more than the flips' ridge limit,
// and relocation only slides its vertices along the crease. Collapsing its shortest usable
// edge (one endpoint joins the other) removes it and keeps the crease, because both
// endpoints lie on it: the surface moves by at most that short edge (issue 12: mAChE's SES
// kept one 122° triangle on a 93° crease, which this removes).
#include <cstddef>
#include <functional>
#include <span>

#include "molmesh/core/geometry.hpp"
#include "molmesh/processing/halfedge_mesh.hpp"

namespace molmesh {

struct PoorTriangleCollapseOptions {
  // A triangle is poor when its smallest angle is below min_angle_deg or its largest above
  // max_angle_deg: the quality floors of the surface pipeline (issue 12), so a mesh that
  // already meets them is left unchanged.
  double min_angle_deg = 27.0;
  double max_angle_deg = 115.0;
  // The collapsed edge may be at most this fraction of the mean edge length around the
  // vertex that goes: no long edges (the height test below is what bounds the change of
  // shape; mAChE's 122° SES triangle collapses an edge of 0.78 times its star's mean).
  double max_edge_ratio = 1.0;
  // The vertex that goes may lie at most this fraction of that mean edge length, or of the
  // whole mesh's mean edge length if that is larger (a sliver's star is tiny), away from the
  // plane of any triangle of the new fan (it keeps creases: a vertex at a crease's bend is
  // not straightened away). 0.15 rather than the valence removal's 0.1: mAChE's 122° SES
  // triangle needs 0.107 (its crease bends by a few degrees at the vertex that goes).
  double max_height_ratio = 0.15;
  // Every new triangle's normal within this angle of the normal of the triangle it replaces
  // (no fold, no new ridge).
  double max_normal_turn_deg = 30.0;
  // The star's quality, min over its triangles of min(smallest angle, (180° - largest) / 2),
  // must rise by at least this much (degrees).
  double min_gain_deg = 0.5;
  // When set, no new triangle's centroid may lie farther than max_centroid_distance (Å) from
  // its projection onto the surface the mesh stands for (as LowValenceRemovalOptions).
  std::function<Vec3(const Vec3&)> project;
  double max_centroid_distance = 0.05;
  // No vertex inside one of these is removed (ProcessingOptions::keep_spheres).
  std::span<const Sphere> keep_spheres;
};

// Visits the faces in index order (deterministic) and, for every live poor one, collapses
// the first of its edges, shortest first and for each edge either endpoint into the other,
// that passes the topology tests (the two endpoints share exactly their two opposite
// vertices, every valence stays >= 3) and the shape and quality tests above. The kept vertex
// does not move; every edit goes through HalfedgeMesh::remove_vertex. Returns the number of
// collapses.
std::size_t collapse_poor_triangles(HalfedgeMesh& mesh,
                                    const PoorTriangleCollapseOptions& options = {});

// Whether some triangle of `mesh` is poor by the options' angle bounds (the test
// collapse_poor_triangles applies to each face).
bool has_poor_triangle(const SurfaceMesh& mesh, const PoorTriangleCollapseOptions& options = {});

}  // namespace molmesh
