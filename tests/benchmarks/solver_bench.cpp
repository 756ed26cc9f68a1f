// MG-PCG vs IC-PCG wall time (setup + solve, tolerance 1e-8) on the absorbing-sphere
// Smoluchowski problem, structured shell meshes of increasing size (tests/solvers).
#include <benchmark/benchmark.h>

#include <map>

#include "../solvers/shell_mesh.hpp"
#include "solvers/physics/smoluchowski.hpp"

namespace {

using namespace molmesh;

const test::ShellHierarchy& hierarchy(int refinement) {
  static std::map<int, test::ShellHierarchy> cache;
  auto it = cache.find(refinement);
  if (it == cache.end()) {
    it = cache
             .emplace(refinement, test::make_shell_hierarchy({.inner_radius = 10.0,
                                                              .outer_radius = 100.0,
                                                              .subdivisions = refinement,
                                                              .radial_layers = 1 << refinement},
                                                             refinement + 1))
             .first;
  }
  return it->second;
}

void run(benchmark::State& state, solvers::Preconditioning p) {
  const auto& h = hierarchy(static_cast<int>(state.range(0)));
  solvers::SmoluchowskiOptions options;
  options.solver.preconditioning = p;
  int iterations = 0;
  for (auto _ : state) {
    const auto r = solvers::solve_smoluchowski(h.meshes[0].mesh, {}, h.prolongations, options);
    iterations = r.solve.iterations;
    benchmark::DoNotOptimize(r.rate_constant_A3_per_s);
  }
  state.counters["cg_iterations"] = iterations;
  state.counters["vertices"] = static_cast<double>(h.meshes[0].mesh.points.size());
}

void BM_MultigridPCG(benchmark::State& state) { run(state, solvers::Preconditioning::kMultigrid); }
void BM_IncompleteCholeskyPCG(benchmark::State& state) {
  run(state, solvers::Preconditioning::kIncompleteCholesky);
}

BENCHMARK(BM_MultigridPCG)->DenseRange(3, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IncompleteCholeskyPCG)->DenseRange(3, 5)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
