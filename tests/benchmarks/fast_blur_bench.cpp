// Exact Gaussian blur (Eq. 1, blur_atoms) against the fast blur of §4.1 (Eq. 2 splatted and
// recursively filtered) on 1a1p, fas2, mAChE and a mAChE tetramer-like assembly (four
// copies translated side by side, 33k atoms). Timing benchmarks per method; the
// "accuracy" benchmarks run once and report, as counters, the volume errors against the
// exact sum of the same Eq. 2 (B_i = kappa r_i^2) and against the default Eq. 1, and the
// dislocation between the marching-cubes surfaces (and, for the small molecules, between the
// processed surfaces). docs/inputs.md and docs/benchmarks.md quote the numbers.
// Note that the exact and fast grids have the same lattice, but Eq. 1's grid may be larger.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <memory>
#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/processing/dislocation.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/volume/fast_blur.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace {

using namespace molmesh;

const Atoms& molecule(const std::string& name) {
  static std::map<std::string, Atoms> cache;
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  Atoms atoms;
  if (name == "mache4") {
    const Atoms& one = molecule("mache");
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (const Atom& a : one) {
      lo = lo.cwiseMin(a.center);
      hi = hi.cwiseMax(a.center);
    }
    // Side by side with 4 Å gaps: a 2 x 2 assembly, as large as a tetramer.
    const Vec3 step = hi - lo + Vec3::Constant(4.0);
    for (int c = 0; c < 4; ++c) {
      const Vec3 shift((c % 2) * step.x(), (c / 2) * step.y(), 0.0);
      for (Atom a : one) {
        a.center += shift;
        atoms.push_back(a);
      }
    }
  } else {
    atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + name + ".pqr");
  }
  return cache.emplace(name, std::move(atoms)).first->second;
}

const char* kMolecules[] = {"1a1p", "fas2", "mache", "mache4"};

void BM_ExactBlur(benchmark::State& state) {
  const Atoms& atoms = molecule(kMolecules[state.range(0)]);
  for (auto _ : state) benchmark::DoNotOptimize(blur_atoms(atoms, BlurOptions{}).values.data());
  state.SetLabel(kMolecules[state.range(0)]);
  state.counters["atoms"] = static_cast<double>(atoms.size());
}

void BM_FastBlur(benchmark::State& state) {
  const Atoms& atoms = molecule(kMolecules[state.range(0)]);
  const auto splat = state.range(1) == 0 ? SplatMethod::kTrilinear : SplatMethod::kNearest;
  for (auto _ : state) {
    benchmark::DoNotOptimize(fast_blur(atoms, BlurOptions{}, splat).values.data());
  }
  state.SetLabel(std::string(kMolecules[state.range(0)]) +
                 (splat == SplatMethod::kTrilinear ? " trilinear" : " nearest"));
}

void BM_FastBlurYoungVanVliet(benchmark::State& state) {
  const Atoms& atoms = molecule(kMolecules[state.range(0)]);
  BlurOptions options;
  Grid grid = fast_blur(atoms, options);
  FastBlurOptions fast;
  fast.kappa = constant_decay_rate(atoms, options.blobbyness);
  fast.design = RecursiveGaussianDesign::kYoungVanVliet3;
  for (auto _ : state) {
    fast_blur_onto(atoms, fast, grid);
    benchmark::DoNotOptimize(grid.values.data());
  }
  state.SetLabel(kMolecules[state.range(0)]);
}

struct Errors {
  double max = 0.0, mean = 0.0;
};

Errors volume_errors(const Grid& a, const Grid& b) {
  Errors e;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    const double d = std::abs(a.values[i] - b.values[i]);
    e.max = std::max(e.max, d);
    e.mean += d;
  }
  e.mean /= static_cast<double>(a.values.size());
  return e;
}

void BM_Accuracy(benchmark::State& state) {
  const std::string name = kMolecules[state.range(0)];
  const auto splat = state.range(1) == 0 ? SplatMethod::kTrilinear : SplatMethod::kNearest;
  const Atoms& atoms = molecule(name);
  const BlurOptions options;
  const double kappa = constant_decay_rate(atoms, options.blobbyness);
  Grid fast, same_kappa, eq1;
  for (auto _ : state) {
    fast = fast_blur(atoms, options, splat);
    same_kappa = blur_atoms(with_constant_decay(atoms, kappa), options);
    eq1 = blur_atoms(atoms, options);
  }
  state.SetLabel(name + (splat == SplatMethod::kTrilinear ? " trilinear" : " nearest"));
  const Errors e2 = volume_errors(fast, same_kappa);
  state.counters["kappa"] = kappa;
  state.counters["err_max_eq2"] = e2.max;
  state.counters["err_mean_eq2"] = e2.mean;
  // Eq. 1's grid may be larger (per-atom decay reaches farther): compare on the same nodes.
  if (eq1.dims == fast.dims) {
    const Errors e1 = volume_errors(fast, eq1);
    state.counters["err_max_eq1"] = e1.max;
    state.counters["err_mean_eq1"] = e1.mean;
  }
  const SurfaceMesh s_fast = marching_cubes(fast, options.isovalue);
  const SurfaceMesh s_eq2 = marching_cubes(same_kappa, options.isovalue);
  const SurfaceMesh s_eq1 = marching_cubes(eq1, options.isovalue);
  const Dislocation d2 = measure_dislocation(s_fast, s_eq2);
  const Dislocation d1 = measure_dislocation(s_fast, s_eq1);
  state.counters["disl_raw_max_eq2"] = d2.max;
  state.counters["disl_raw_mean_eq2"] = d2.mean;
  state.counters["disl_raw_max_eq1"] = d1.max;
  state.counters["disl_raw_mean_eq1"] = d1.mean;
  if (name == "1a1p" || name == "fas2") {
    const SurfaceMesh p_fast = process_surface(s_fast, ProcessingOptions{}).mesh;
    const SurfaceMesh p_eq2 = process_surface(s_eq2, ProcessingOptions{}).mesh;
    const SurfaceMesh p_eq1 = process_surface(s_eq1, ProcessingOptions{}).mesh;
    state.counters["disl_final_mean_eq2"] = measure_dislocation(p_fast, p_eq2).mean;
    state.counters["disl_final_max_eq2"] = measure_dislocation(p_fast, p_eq2).max;
    state.counters["disl_final_mean_eq1"] = measure_dislocation(p_fast, p_eq1).mean;
    state.counters["disl_final_max_eq1"] = measure_dislocation(p_fast, p_eq1).max;
  }
}

void molecules(benchmark::internal::Benchmark* b) {
  for (int m = 0; m < 4; ++m) b->Args({m});
}
void molecules_and_splats(benchmark::internal::Benchmark* b) {
  for (int m = 0; m < 4; ++m) {
    b->Args({m, 0});
    b->Args({m, 1});
  }
}

BENCHMARK(BM_ExactBlur)->Apply(molecules)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_FastBlur)->Apply(molecules_and_splats)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_FastBlurYoungVanVliet)->Apply(molecules)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK(BM_Accuracy)->Apply(molecules_and_splats)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

// MOLMESH_BENCH_THREADS=1 runs everything on one thread, so that the CPU column is the whole
// work even on a loaded machine (the numbers in docs/benchmarks.md).
int main(int argc, char** argv) {
  std::unique_ptr<tbb::global_control> threads;
  if (const char* n = std::getenv("MOLMESH_BENCH_THREADS")) {
    threads = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                    static_cast<std::size_t>(std::atoi(n)));
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
