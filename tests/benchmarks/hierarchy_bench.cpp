// Does the reverse Cuthill-McKee renumbering of volume meshes pay off? Times a sparse
// matrix-vector product and 50 CG iterations with the P1 stiffness matrix (+ lumped mass,
// so it is definite) of a real exterior mesh (fasciculin-2), in TetGen's numbering and
// after renumbering; also times the renumbering and the volume prolongation themselves.
#include <benchmark/benchmark.h>

#include <Eigen/IterativeLinearSolvers>
#include <Eigen/LU>
#include <filesystem>

#include "molmesh/hierarchy/renumber.hpp"
#include "molmesh/hierarchy/transfer.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"
#include "molmesh/processing/process_surface.hpp"
#include "molmesh/tetmesh/tetrahedralize.hpp"

namespace {

using namespace molmesh;

struct Meshes {
  TetMesh tetgen_order;
  TetMesh rcm_order;
  TetMesh coarse;
};

const Meshes& meshes() {
  static const Meshes m = [] {
    const auto atoms = read_atoms(std::filesystem::path(MOLMESH_TEST_DATA_DIR) / "fas2.pqr");
    SurfacePipelineOptions surface_options;
    surface_options.surface = SurfaceKind::kGaussian;  // the paper's, as the recorded numbers
    surface_options.raw = true;
    const auto raw = surface_from_atoms(atoms, surface_options).surface;
    ProcessingOptions processing;
    processing.t0 = {0.1};
    processing.record_stages = false;
    const auto fine_surface = process_surface(raw, processing).mesh;
    processing.t0 = {0.3};
    const auto coarse_surface = process_surface(fine_surface, processing).mesh;
    TetMeshOptions tet;
    tet.domain = Domain::full;
    tet.outer_radius = 60.0;
    Meshes out;
    out.tetgen_order = tetrahedralize(fine_surface, atoms, tet);
    out.rcm_order = permute_vertices(out.tetgen_order, reverse_cuthill_mckee(out.tetgen_order));
    out.coarse = tetrahedralize(coarse_surface, atoms, tet);
    return out;
  }();
  return m;
}

Eigen::SparseMatrix<double, Eigen::RowMajor> stiffness(const TetMesh& mesh) {
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(mesh.tetrahedra.size() * 16);
  for (const auto& t : mesh.tetrahedra) {
    Eigen::Matrix3d e;
    const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
    for (int k = 0; k < 3; ++k)
      e.row(k) = (mesh.points[static_cast<std::size_t>(t[k + 1])] - a).transpose();
    const double volume = e.determinant() / 6.0;
    const Eigen::Matrix3d inv = e.inverse();  // columns: gradients of barycentrics 1..3
    Eigen::Matrix<double, 3, 4> g;
    g.col(0) = -inv.rowwise().sum();
    g.rightCols<3>() = inv;
    const Eigen::Matrix4d local = volume * g.transpose() * g;
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) triplets.emplace_back(t[i], t[j], local(i, j));
      triplets.emplace_back(t[i], t[i], volume / 4.0);
    }
  }
  const auto n = static_cast<Eigen::Index>(mesh.points.size());
  Eigen::SparseMatrix<double, Eigen::RowMajor> k(n, n);
  k.setFromTriplets(triplets.begin(), triplets.end());
  return k;
}

void BM_SpMV(benchmark::State& state) {
  const auto& mesh = state.range(0) ? meshes().rcm_order : meshes().tetgen_order;
  const auto k = stiffness(mesh);
  const Eigen::VectorXd x = Eigen::VectorXd::Ones(k.cols());
  Eigen::VectorXd y(k.rows());
  for (auto _ : state) {
    y.noalias() = k * x;
    benchmark::DoNotOptimize(y.data());
  }
  state.counters["vertices"] = static_cast<double>(mesh.points.size());
  state.counters["bandwidth"] = vertex_bandwidth(mesh);
}
BENCHMARK(BM_SpMV)->Arg(0)->Arg(1)->ArgName("rcm")->Unit(benchmark::kMicrosecond);

void BM_CG50(benchmark::State& state) {
  const auto& mesh = state.range(0) ? meshes().rcm_order : meshes().tetgen_order;
  const auto k = stiffness(mesh);
  const Eigen::VectorXd b = Eigen::VectorXd::Ones(k.rows());
  Eigen::ConjugateGradient<Eigen::SparseMatrix<double, Eigen::RowMajor>,
                           Eigen::Lower | Eigen::Upper, Eigen::IdentityPreconditioner>
      cg;
  cg.setMaxIterations(50);
  cg.setTolerance(1e-30);
  cg.compute(k);
  for (auto _ : state) {
    Eigen::VectorXd x = cg.solve(b);
    benchmark::DoNotOptimize(x.data());
  }
}
BENCHMARK(BM_CG50)->Arg(0)->Arg(1)->ArgName("rcm")->Unit(benchmark::kMillisecond);

void BM_ReverseCuthillMcKee(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(reverse_cuthill_mckee(meshes().tetgen_order));
}
BENCHMARK(BM_ReverseCuthillMcKee)->Unit(benchmark::kMillisecond);

void BM_VolumeProlongation(benchmark::State& state) {
  for (auto _ : state) {
    benchmark::DoNotOptimize(volume_prolongation(meshes().coarse, meshes().rcm_order));
  }
  state.counters["fine_vertices"] = static_cast<double>(meshes().rcm_order.points.size());
}
BENCHMARK(BM_VolumeProlongation)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
