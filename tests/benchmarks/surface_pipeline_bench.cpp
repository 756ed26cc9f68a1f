// Whole surface pipeline (blur → marching cubes → improve → coarsen → smooth → improve),
// the paper's parameters. Target: mache ≤ 2 s wall on 2 cores (GAMer 1: 9.4 s).
// Run: build/tests/benchmarks/surface_pipeline_bench --benchmark_filter=mache
#include <benchmark/benchmark.h>

#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace {

void surface_pipeline(benchmark::State& state, const std::string& file, bool record_stages) {
  const molmesh::Atoms atoms = molmesh::read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + file);
  molmesh::BlurOptions blur;  // B = -0.5, 0.5 Å, isovalue 1
  molmesh::ProcessingOptions options;
  options.record_stages = record_stages;
  std::size_t vertices = 0;
  for (auto _ : state) {
    const molmesh::SurfaceMesh raw = molmesh::marching_cubes(molmesh::blur_atoms(atoms, blur), 1.0);
    const molmesh::ProcessingResult result = molmesh::process_surface(raw, options);
    vertices = result.mesh.points.size();
    benchmark::DoNotOptimize(result.mesh.points.data());
  }
  state.counters["vertices"] = static_cast<double>(vertices);
}

void process_only(benchmark::State& state, const std::string& file) {
  const molmesh::Atoms atoms = molmesh::read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + file);
  const molmesh::SurfaceMesh raw = molmesh::marching_cubes(molmesh::blur_atoms(atoms, {}), 1.0);
  molmesh::ProcessingOptions options;
  options.record_stages = false;
  for (auto _ : state) {
    const molmesh::ProcessingResult result = molmesh::process_surface(raw, options);
    benchmark::DoNotOptimize(result.mesh.points.data());
  }
}

}  // namespace

BENCHMARK_CAPTURE(surface_pipeline, 1a1p, std::string("1a1p.pqr"), false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(surface_pipeline, fas2, std::string("fas2.pqr"), false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_CAPTURE(surface_pipeline, mache, std::string("mache.pqr"), false)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);
BENCHMARK_CAPTURE(surface_pipeline, mache_with_stage_stats, std::string("mache.pqr"), true)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK_CAPTURE(process_only, mache, std::string("mache.pqr"))
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(3);

BENCHMARK_MAIN();
