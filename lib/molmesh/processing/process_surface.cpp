#include "molmesh/processing/process_surface.hpp"

#include <chrono>
#include <cstdio>
#include <numeric>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/processing/coarsen.hpp"
#include "molmesh/processing/edge_flips.hpp"
#include "molmesh/processing/halfedge_mesh.hpp"
#include "molmesh/processing/low_valence_removal.hpp"
#include "molmesh/processing/poor_triangle_collapse.hpp"
#include "molmesh/processing/processing_option_specs.hpp"
#include "molmesh/processing/project_vertices.hpp"
#include "molmesh/processing/untangle.hpp"

namespace molmesh {
namespace {

using Clock = std::chrono::steady_clock;

std::string format_t0(double t0) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", t0);
  return buffer;
}

class StageTimer {
 public:
  StageTimer(ProcessingResult& result, bool record) : result_(result), record_(record) {}
  template <class F>
  void run(const std::string& name, F&& body) {
    const auto start = Clock::now();
    body();
    ProcessingStage stage;
    stage.name = name;
    stage.seconds = seconds_since(start);
    if (record_) stage.stats = compute_surface_stats(result_.mesh);
    result_.stages.push_back(std::move(stage));
  }

 private:
  ProcessingResult& result_;
  bool record_;
};

// Compacts an edited mesh into the result, composing the provenance (output vertex →
// input vertex of process_surface) through the compaction.
void take_edited(ProcessingResult& result, const HalfedgeMesh& editable) {
  HalfedgeMesh::Compacted compact = editable.to_surface_mesh();
  for (int& p : compact.new_to_old) p = result.provenance[p];
  result.mesh = std::move(compact.mesh);
  result.provenance = std::move(compact.new_to_old);
}

ProcessingResult process_centred(const SurfaceMesh& input, const ProcessingOptions& options,
                                 const Reporter& reporter);

}  // namespace

void ProcessingOptions::validate() const {
  const ProcessingOptionSpecs& specs = kProcessingOptionSpecs;
  for (double threshold : t0) check_range("t0", kT0Range, threshold);
  check_range(specs.rings, rings);
  check_range(specs.alpha, alpha);
  check_range(specs.beta, beta);
  check_range(specs.sweeps, improve.sweeps);
  check_range(specs.feature_weight, improve.feature_weight);
  check_range(specs.smooth_iterations, smoothing.normal_iterations);
  check_range(specs.cleanup_rounds, cleanup_rounds);
}

ProcessingResult process_surface(const SurfaceMesh& input, const ProcessingOptions& options,
                                 const Reporter& reporter) {
  options.validate();
  // Local frame: the processing's geometric tests lose their digits on coordinates far from
  // the origin (a molecule at 1e7 Å came out with 1e6 times its area, issue 18). Process
  // around the bounding-box centre, then shift back.
  if (input.points.empty()) return process_centred(input, options, reporter);
  Vec3 lo = input.points.front(), hi = lo;
  for (const Vec3& p : input.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec3 centre = (lo + hi) / 2.0;
  if (!centre.allFinite()) return process_centred(input, options, reporter);
  SurfaceMesh local = input;
  for (Vec3& p : local.points) p -= centre;
  ProcessingOptions local_options = options;
  for (Sphere& s : local_options.keep_spheres) s.center -= centre;
  if (options.project) {
    // The projection works in the caller's coordinates.
    local_options.project = [project = options.project, centre](const Vec3& p) {
      return Vec3(project(p + centre) - centre);
    };
  }
  if (options.settle) {
    local_options.settle = [settle = options.settle, centre](const Vec3& p) {
      return Vec3(settle(p + centre) - centre);
    };
  }
  ProcessingResult result = process_centred(local, local_options, reporter);
  for (Vec3& p : result.mesh.points) p += centre;
  return result;
}

namespace {

ProcessingResult process_centred(const SurfaceMesh& input, const ProcessingOptions& options,
                                 const Reporter& reporter) {
  ProcessingResult result;
  result.mesh = input;
  result.provenance.resize(input.points.size());
  std::iota(result.provenance.begin(), result.provenance.end(), 0);
  StageTimer timer(result, options.record_stages);

  ImproveOptions improve = options.improve;
  improve.rings = options.rings;
  FlipOptions flips;

  // Removes the valence-3 and -4 vertices that flips cannot fix, then lets the valence flips
  // spread what is left; the improvement that follows evens the angles out.
  auto remove_low_valence = [&](const std::string& suffix) {
    timer.run("valence" + suffix, [&] {
      HalfedgeMesh editable(result.mesh);
      LowValenceRemovalOptions removal;
      removal.keep_spheres = options.keep_spheres;
      removal.project = options.project;
      remove_low_valence_vertices(editable, removal);
      flip_edges_for_valence(editable, flips, options.valence_stage_flip_min_angle_deg);
      take_edited(result, editable);
    });
  };

  // `first`: the improvement of the raw marching-cubes mesh, whose vertices coarsening
  // removes by the thousand anyway.
  auto improve_and_flip = [&](const std::string& suffix, int sweeps, bool worklist = false,
                              bool first = false) {
    // Only when coarsening: without it every input vertex is kept (`molmesh improve
    // --no-coarsen` keeps a user mesh's vertices).
    if (!first && !options.t0.empty() && options.remove_low_valence && options.flips &&
        options.valence_flips)
      remove_low_valence(suffix);
    ImproveOptions pass = improve;
    pass.sweeps = sweeps;
    pass.worklist = pass.worklist || worklist;
    timer.run("improve" + suffix, [&] {
      improve_angles(result.mesh, pass, reporter);
      project_vertices(result.mesh, options.project);
    });
    if (options.flips) {
      timer.run("flip" + suffix, [&] {
        if (!options.valence_flips) {
          flip_edges_for_angles(result.mesh, flips);
          return;
        }
        // Valence near 6 is what lets relocation reach ~60° angles; the angle flips then
        // repair whatever the valence flips left sharp.
        HalfedgeMesh editable(result.mesh);
        flip_edges_for_valence(editable, flips, options.valence_flip_min_angle_deg);
        flip_edges_for_angles(editable, flips);
        take_edited(result, editable);
      });
    }
  };

  improve_and_flip("", options.initial_sweeps, false, true);
  for (double t0 : options.t0) {
    const std::string tag = " T0=" + format_t0(t0);
    timer.run("coarsen" + tag, [&] {
      CoarsenOptions co;
      co.t0 = t0;
      co.alpha = options.alpha;
      co.beta = options.beta;
      co.rings = options.rings;
      co.keep_spheres = options.keep_spheres;
      CoarsenResult coarse = coarsen(result.mesh, co, reporter);
      for (int& p : coarse.provenance) p = result.provenance[p];
      result.mesh = std::move(coarse.mesh);
      result.provenance = std::move(coarse.provenance);
    });
    timer.run("smooth" + tag, [&] {
      smooth_normals(result.mesh, options.smoothing, reporter);
      project_vertices(result.mesh, options.project);
    });
    improve_and_flip(tag, improve.sweeps);
  }
  for (int round = 0; round < options.cleanup_rounds; ++round) {
    improve_and_flip(" cleanup " + std::to_string(round + 1), improve.sweeps,
                     options.cleanup_worklist);
  }
  if (options.settle && !options.project) {
    timer.run("settle", [&] {
      project_vertices_keeping_angles(result.mesh, options.settle, options.settle_floor_deg);
    });
  }
  // What the cleanup left outside the floors, mostly tiny triangles on creases, is collapsed
  // last, so the edit stays local: a mesh inside the floors is not touched (and only with
  // coarsening: without it every input vertex is kept).
  PoorTriangleCollapseOptions poor;
  poor.keep_spheres = options.keep_spheres;
  poor.project = options.project;
  if (options.collapse_poor_triangles && !options.t0.empty() &&
      has_poor_triangle(result.mesh, poor)) {
    timer.run("collapse", [&] {
      HalfedgeMesh editable(result.mesh);
      // A collapse can leave a neighbour poor that the pass had already visited.
      for (int pass = 0; pass < 3 && collapse_poor_triangles(editable, poor) > 0; ++pass) {
      }
      take_edited(result, editable);
    });
  }
  // The steps above can, rarely, push one sheet through a close neighbour (issue 18:
  // TetGen refused fas2 at B = -2); undo that locally.
  timer.run("untangle", [&] { untangle(result.mesh, input, result.provenance); });
  return result;
}

}  // namespace
}  // namespace molmesh
