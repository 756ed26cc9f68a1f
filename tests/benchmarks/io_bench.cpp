// Speed of the readers and writers on real molecules and mesh/volume sizes the pipeline
// produces (mAChE surface meshes have ~10^5 vertices; blurred volumes ~10^6 samples).
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/volume_io.hpp"

namespace {

const std::filesystem::path kData = MOLMESH_TEST_DATA_DIR;

std::filesystem::path scratch(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / "molmesh_io_bench";
  std::filesystem::create_directories(dir);
  return dir / name;
}

void BM_ReadPqrMache(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(molmesh::read_atoms(kData / "mache.pqr"));
  state.SetItemsProcessed(state.iterations() * 8279);
}
BENCHMARK(BM_ReadPqrMache)->Unit(benchmark::kMillisecond);

void BM_ReadPdb1a1p(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(molmesh::read_atoms(kData / "1a1p.pdb"));
}
BENCHMARK(BM_ReadPdb1a1p)->Unit(benchmark::kMillisecond);

// A torus of nu x nv vertices and 2 nu nv triangles.
molmesh::SurfaceMesh torus(int nu, int nv) {
  molmesh::SurfaceMesh m;
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      const double u = 2 * M_PI * i / nu, v = 2 * M_PI * j / nv;
      m.points.emplace_back((30 + 8 * std::cos(v)) * std::cos(u),
                            (30 + 8 * std::cos(v)) * std::sin(u), 8 * std::sin(v));
    }
  auto id = [&](int i, int j) { return (i % nu) * nv + j % nv; };
  for (int i = 0; i < nu; ++i)
    for (int j = 0; j < nv; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

void BM_SurfaceRoundTrip(benchmark::State& state, const char* ext) {
  const molmesh::SurfaceMesh mesh = torus(400, 250);  // 100k vertices, 200k triangles
  const auto path = scratch(std::string("torus") + ext);
  for (auto _ : state) {
    molmesh::write_surface_mesh(path, mesh);
    benchmark::DoNotOptimize(molmesh::read_surface_mesh(path));
  }
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
}
BENCHMARK_CAPTURE(BM_SurfaceRoundTrip, off, ".off")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SurfaceRoundTrip, ply, ".ply")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SurfaceRoundTrip, obj, ".obj")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_SurfaceRoundTrip, stl, ".stl")->Unit(benchmark::kMillisecond);

void BM_VolumeRoundTrip(benchmark::State& state, const char* ext) {
  molmesh::Grid g;
  g.dims = {129, 129, 129};
  g.spacing = molmesh::Vec3(0.5, 0.5, 0.5);
  g.values.resize(g.size());
  for (std::size_t i = 0; i < g.values.size(); ++i)
    g.values[i] = std::sin(1e-3 * static_cast<double>(i));
  const auto path = scratch(std::string("grid") + ext);
  for (auto _ : state) {
    molmesh::write_volume(path, g);
    benchmark::DoNotOptimize(molmesh::read_volume(path));
  }
  state.counters["MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
}
BENCHMARK_CAPTURE(BM_VolumeRoundTrip, dx, ".dx")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_VolumeRoundTrip, mrc, ".mrc")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
