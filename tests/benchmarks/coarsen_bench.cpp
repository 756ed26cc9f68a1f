// Speed of feature-adaptive coarsening (Eq. 6) on the mAChE monomer surface (~100k raw
// vertices), on the raw marching-cubes mesh and on the mesh after the first quality
// improvement (what process_surface hands to coarsen). Counters report the vertex counts.
#include <benchmark/benchmark.h>

#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/processing/coarsen.hpp"
#include "molmesh/processing/edge_flips.hpp"
#include "molmesh/processing/improve_angles.hpp"

namespace {

const molmesh::SurfaceMesh& mache_raw() {
  static const molmesh::SurfaceMesh mesh = [] {
    const molmesh::Atoms atoms =
        molmesh::read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/mache.pqr");
    molmesh::SurfacePipelineOptions options;
    options.surface = molmesh::SurfaceKind::kGaussian;  // the paper's, as the recorded numbers
    options.raw = true;
    return molmesh::surface_from_atoms(atoms, options).raw;
  }();
  return mesh;
}

const molmesh::SurfaceMesh& mache_improved() {
  static const molmesh::SurfaceMesh mesh = [] {
    molmesh::SurfaceMesh m = mache_raw();
    molmesh::ImproveOptions options;
    options.sweeps = 3;
    molmesh::improve_angles(m, options);
    molmesh::flip_edges_for_angles(m);
    return m;
  }();
  return mesh;
}

void run(benchmark::State& state, const molmesh::SurfaceMesh& input) {
  molmesh::CoarsenResult result;
  for (auto _ : state) {
    result = molmesh::coarsen(input, molmesh::CoarsenOptions{});
    benchmark::DoNotOptimize(result.mesh.points.data());
  }
  state.counters["vertices_in"] = static_cast<double>(input.points.size());
  state.counters["vertices_out"] = static_cast<double>(result.mesh.points.size());
  state.counters["passes"] = result.passes;
}

void BM_CoarsenMacheRaw(benchmark::State& state) { run(state, mache_raw()); }
void BM_CoarsenMacheImproved(benchmark::State& state) { run(state, mache_improved()); }

BENCHMARK(BM_CoarsenMacheRaw)->Unit(benchmark::kMillisecond)->MinTime(2.0)->MeasureProcessCPUTime();
BENCHMARK(BM_CoarsenMacheImproved)
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0)
    ->MeasureProcessCPUTime();

}  // namespace

BENCHMARK_MAIN();
