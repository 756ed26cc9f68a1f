#pragma once
// The surface post-processing of GAMer (Fig. 1), in one call: quality improvement →
// feature-adaptive coarsening → normal-based smoothing → quality improvement, repeated once
// per coarsening threshold, with edge flips where they raise angles, and a final
// worst-triangle cleanup. Every stage is timed and measured.
#include <functional>
#include <string>
#include <vector>

#include "molmesh/core/geometry.hpp"
#include "molmesh/core/reporter.hpp"
#include "molmesh/processing/improve_angles.hpp"
#include "molmesh/processing/normal_smoothing.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/surface/surface_stats.hpp"

namespace molmesh {

struct ProcessingOptions {
  // One coarsening round per threshold T0 (Eq. 6), in order; empty = improve only.
  std::vector<double> t0 = {0.2};
  double alpha = 1.0;                // Eq. 6 exponent on the longest incident edge
  double beta = 1.0;                 // Eq. 6 exponent on λ2/λ1
  int rings = 2;                     // k-ring of the structure tensor (improvement and coarsening)
  std::vector<Sphere> keep_spheres;  // no vertex inside is deleted by coarsening
  ImproveOptions improve;            // improve.rings is overwritten by `rings`
  // Sweeps of the first improvement, on the dense raw mesh: it only has to straighten the
  // marching-cubes slivers before coarsening; more sweeps cost time and change nothing
  // measurable after coarsening (docs/processing.md).
  int initial_sweeps = 3;
  NormalSmoothingOptions smoothing;
  bool flips = true;  // edge flips for angles after each improvement
  // Also flip towards valence 6 (never across ridges, never below this smaller min angle).
  bool valence_flips = true;
  double valence_flip_min_angle_deg = 30.0;
  // Before every improvement after coarsening, remove the valence-3 and -4 vertices of flat
  // regions that flips cannot fix (processing/low_valence_removal.hpp), then flip towards
  // valence 6 down to a smaller minimum angle than the other flips, since the improvement
  // that follows evens the angles out. Needs flips, valence_flips and coarsening (without
  // coarsening every input vertex is kept). On eleven proteins it lifts the share of angles in
  // [40°, 80°] from 90.8–92.6 % to 95.2–96.5 % (docs/processing.md).
  bool remove_low_valence = true;
  double valence_stage_flip_min_angle_deg = 15.0;
  // After the cleanup rounds, collapse the short edges of the triangles still outside the
  // quality floors (below 27° or above 115°), which flips and relocation cannot repair,
  // such as tiny triangles on creases (processing/poor_triangle_collapse.hpp). A mesh inside
  // the floors is unchanged. Only with coarsening.
  bool collapse_poor_triangles = true;
  // Final passes of improvement + flips aimed at the worst triangles (see docs/processing.md).
  // Five: with the valence removal the minimum angle still rises in the fourth and fifth
  // (the worst of eleven proteins 29.99° after four, 30.49° after five).
  int cleanup_rounds = 5;
  // The cleanup improvements revisit only vertices whose neighbourhood still moves
  // (ImproveOptions::worklist). Off: on mache it ends 0.04° and 0.03 % lower
  // (docs/processing.md), and quality comes first.
  bool cleanup_worklist = false;
  bool record_stages = true;  // compute SurfaceStats after every stage
  // Optional: moves a point onto the surface the mesh stands for (the distance-field
  // surfaces set volume/level_set_projection.hpp's, the Gaussian one with
  // SurfacePipelineOptions::keep_on_surface a Newton projection onto Eq. 1). When set, every
  // vertex is projected after each stage that moves vertices (improvement, smoothing), so the
  // processed mesh stays on that surface instead of shrinking with smoothing; a vertex whose
  // projection would turn one of its triangles over stays put (processing/project_vertices.hpp).
  // Must be thread-safe.
  std::function<Vec3(const Vec3&)> project;
  // Optional, used only when `project` is unset: the same kind of projection, applied once
  // after the cleanup rounds (before the poor-triangle collapse), and only to the vertices
  // whose triangles' angles stay within [settle_floor_deg, 180° - 2·settle_floor_deg] or get no
  // worse (processing/project_vertices.hpp, project_vertices_keeping_angles). For the
  // distance-field surfaces, whose projection after every stage pulls vertices onto creases
  // and cusps and costs their angles: smoothing leaves the mesh up to a few tenths of an Å
  // inside the surface, which shrinks the dielectric boundary (the Born ion's energy +1.75 %
  // without, +0.87 % with, docs/surface.md). Must be thread-safe.
  std::function<Vec3(const Vec3&)> settle;
  double settle_floor_deg = 34.0;

  // Throws molmesh::Error naming the member (core/error.hpp) for a value outside the range of
  // its entry in processing/processing_option_specs.hpp (the front ends' ranges), NaN or inf
  // included, or a T0 outside kT0Range. process_surface() calls it first.
  void validate() const;
};

struct ProcessingStage {
  std::string name;  // "improve", "coarsen T0=0.2", "flip", "smooth", "valence", "cleanup"
  double seconds = 0.0;
  SurfaceStats stats;  // of the mesh after this stage (empty if !record_stages)
};

struct ProcessingResult {
  SurfaceMesh mesh;
  std::vector<int> provenance;  // output vertex -> input vertex
  std::vector<ProcessingStage> stages;
};

// Throws molmesh::Error for an input that is not a closed oriented manifold (coarsening
// needs one) or for invalid options (ProcessingOptions::validate()). Deterministic and independent
// of the thread count.
ProcessingResult process_surface(const SurfaceMesh& input, const ProcessingOptions& options,
                                 const Reporter& reporter = {});

}  // namespace molmesh
