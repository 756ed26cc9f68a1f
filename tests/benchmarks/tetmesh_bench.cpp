// TetGen meshing time on processed molecular surfaces (blur B=-0.5, 0.5 Å, isovalue 1,
// marching cubes, process_surface defaults), compared with GAMer 1's 2.3 s (interior) and
// 12.6 s (full, 3x sphere) on mAChE. The surfaces are made once, outside the timing.
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace {

using namespace molmesh;

struct Input {
  Atoms atoms;
  SurfaceMesh surface;
};

const Input& input(const std::string& name) {
  static std::map<std::string, Input> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Input in;
  in.atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + name);
  BlurOptions blur;
  blur.spacing = 0.5;
  blur.blobbyness = -0.5;
  blur.isovalue = 1.0;
  const SurfaceMesh raw = marching_cubes(blur_atoms(in.atoms, blur), 1.0);
  in.surface = process_surface(raw, ProcessingOptions{}).mesh;
  return cache.emplace(name, std::move(in)).first->second;
}

void BM_Tetmesh(benchmark::State& state, const std::string& name, Domain domain, double ratio) {
  const Input& in = input(name);
  TetMeshOptions o;
  o.domain = domain;
  o.sphere_ratio = ratio;
  TetMeshReport r;
  std::size_t tets = 0;
  for (auto _ : state) {
    const TetMesh m = tetrahedralize(in.surface, in.atoms, o, {}, &r);
    tets = m.tetrahedra.size();
    benchmark::DoNotOptimize(tets);
  }
  state.counters["surface_vertices"] = static_cast<double>(in.surface.points.size());
  state.counters["tets"] = static_cast<double>(tets);
  state.counters["tetgen_s"] = r.seconds;
  state.counters["atoms_as_nodes"] = static_cast<double>(r.atoms_as_nodes);
}

BENCHMARK_CAPTURE(BM_Tetmesh, fas2_interior, "fas2.pqr", Domain::interior, 40.0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Tetmesh, fas2_full_ratio40, "fas2.pqr", Domain::full, 40.0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Tetmesh, mache_interior, "mache.pqr", Domain::interior, 40.0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Tetmesh, mache_full_ratio3, "mache.pqr", Domain::full, 3.0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK_CAPTURE(BM_Tetmesh, mache_full_ratio40, "mache.pqr", Domain::full, 40.0)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
