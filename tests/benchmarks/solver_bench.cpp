// MG-PCG vs IC-PCG wall time (setup + solve, tolerance 1e-8): the absorbing-sphere
// Smoluchowski problem on structured shell meshes of increasing size (tests/solvers), and
// the sample problem on the finest level of a real mAChE exterior hierarchy (the gorge
// absorbs, the rest of the surface reflects; examples/run_mache_diffusion.sh).
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>

#include "../solvers/shell_mesh.hpp"
#include "molmesh/hierarchy/build_hierarchy.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "solvers/fem/p1_assembly.hpp"
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

// The sample run's hierarchy (outer radius 150 Å, T0 0.1/0.3/0.5/0.7, default grading).
const Hierarchy& mache() {
  static const Hierarchy h = [] {
    const auto atoms = read_atoms(std::filesystem::path(MOLMESH_TEST_DATA_DIR) / "mache.pqr");
    SurfacePipelineOptions surface_options;
    surface_options.surface = SurfaceKind::kGaussian;  // the paper's, as the recorded numbers
    surface_options.raw = true;
    const auto raw = surface_from_atoms(atoms, surface_options).surface;
    HierarchyOptions options;
    options.tetmesh.domain = Domain::exterior;
    options.tetmesh.outer_radius = 150.0;
    options.tetmesh.active_site =
        read_spheres(std::filesystem::path(MOLMESH_EXAMPLES_DIR) / "mache-gorge.spheres");
    options.processing.keep_spheres = options.tetmesh.active_site;
    return build_hierarchy(raw, atoms, options);
  }();
  return h;
}

// smoothing: take (sweeps, blocks) from the benchmark arguments instead of the defaults.
void run_mache(benchmark::State& state, solvers::Preconditioning p, bool mesh_operators = false,
               bool smoothing = false) {
  const Hierarchy& h = mache();
  std::vector<SparseMatrix> prolongations;
  for (const auto& t : h.transfers) prolongations.push_back(t.volume);
  solvers::SmoluchowskiOptions options;
  options.absorbing_markers = {markers::kActiveSite};
  options.solver.preconditioning = p;
  if (smoothing) {
    options.solver.multigrid.smoothing_sweeps = static_cast<int>(state.range(0));
    options.solver.multigrid.smoothing_blocks = static_cast<int>(state.range(1));
  }
  std::vector<solvers::CoarseLevel> coarse;
  if (mesh_operators)
    for (std::size_t l = 1; l < h.levels.size(); ++l) coarse.push_back({&h.levels[l].volume, {}});
  solvers::SmoluchowskiResult r;
  for (auto _ : state) {
    r = solvers::solve_smoluchowski(h.levels[0].volume, {}, prolongations, options, {}, coarse);
    benchmark::DoNotOptimize(r.rate_constant_A3_per_s);
  }
  state.counters["cg_iterations"] = r.solve.iterations;
  state.counters["unknowns"] = r.unknowns;
  state.counters["setup_ms"] = 1e3 * r.solve.setup_time_s;
  state.counters["cg_ms"] = 1e3 * r.solve.solve_time_s;
}

// The CLI's default: coarse operators discretised on the coarse meshes.
void BM_MacheMultigridPCG(benchmark::State& state) {
  run_mache(state, solvers::Preconditioning::kMultigrid, true);
}
// Galerkin coarse operators P^T A P (`--coarse-operators galerkin`).
void BM_MacheMultigridPCGGalerkin(benchmark::State& state) {
  run_mache(state, solvers::Preconditioning::kMultigrid);
}
// The smoother's trade-off: Gauss-Seidel sweeps per side against row blocks in parallel.
void BM_MacheSmoothing(benchmark::State& state) {
  run_mache(state, solvers::Preconditioning::kMultigrid, true, true);
}
void BM_MacheIncompleteCholeskyPCG(benchmark::State& state) {
  run_mache(state, solvers::Preconditioning::kIncompleteCholesky);
}

// P1 stiffness assembly of the finest mAChE exterior level (76,712 vertices, 413,922 cells):
// every solve starts with it, and the mesh coarse operators repeat it on each level.
void BM_AssembleMacheFine(benchmark::State& state) {
  const TetMesh& mesh = mache().levels[0].volume;
  const std::vector<double> ones(mesh.tetrahedra.size(), 1.0);
  for (auto _ : state) benchmark::DoNotOptimize(solvers::assemble_stiffness(mesh, ones));
  state.counters["cells"] = static_cast<double>(mesh.tetrahedra.size());
}

BENCHMARK(BM_AssembleMacheFine)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MacheMultigridPCG)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MacheMultigridPCGGalerkin)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MacheIncompleteCholeskyPCG)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MacheSmoothing)
    ->ArgNames({"sweeps", "blocks"})
    ->Args({1, 1})
    ->Args({1, 2})
    ->Args({1, 4})
    ->Args({2, 1})
    ->Args({2, 2})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MultigridPCG)->DenseRange(3, 5)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_IncompleteCholeskyPCG)->DenseRange(3, 5)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
