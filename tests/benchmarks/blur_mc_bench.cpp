// Blur + marching cubes on mache.pqr (8279 atoms) at the paper's parameters.
#include <benchmark/benchmark.h>

#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace {

const molmesh::Atoms& mache() {
  static const molmesh::Atoms atoms =
      molmesh::read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/mache.pqr");
  return atoms;
}

void BM_Blur(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(molmesh::blur_atoms(mache(), {}));
}

void BM_MarchingCubes(benchmark::State& state) {
  const molmesh::Grid grid = molmesh::blur_atoms(mache(), {});
  for (auto _ : state) benchmark::DoNotOptimize(molmesh::marching_cubes(grid, 1.0));
}

void BM_BlurAndMarchingCubes(benchmark::State& state) {
  std::size_t vertices = 0;
  for (auto _ : state) {
    const molmesh::SurfaceMesh mesh =
        molmesh::marching_cubes(molmesh::blur_atoms(mache(), {}), 1.0);
    vertices = mesh.points.size();
  }
  state.counters["vertices"] = static_cast<double>(vertices);
}

BENCHMARK(BM_Blur)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_MarchingCubes)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_BlurAndMarchingCubes)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
