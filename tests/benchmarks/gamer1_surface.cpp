// The original GAMer 1 (Debian libfetk-dev's libgamer) on the paper's parameters, for the
// end-to-end benchmark (tests/benchmarks/run_pipeline_bench.py) to time beside molmesh in
// the same run. Not a molmesh code path: it exists only to measure the reference.
//
//   gamer1_surface INPUT.pqr [OUT.off]
//
// The Gaussian volume (B = -0.5, 0.5 Å, isovalue 1) comes from molmesh's exact blur,
// because libgamer's own SurfaceMesh_readPDB has its blobbyness and isovalue compiled in
// (-0.2 and 2.5). GAMer then runs what its MolecularMesh driver runs on a new surface
// (SmoothMolecularSurface): marching cubes, 15 quality-improvement sweeps without flips,
// coarsening once with T0 = 0.2 (alpha = beta = 1; the driver's normal-angle limit 0.5),
// improvement with flips until it converges (at most 30 rounds), normal-based smoothing.
// Prints one JSON line last (libgamer prints its progress before it): seconds per stage
// (the blur excluded from gamer_seconds, so the comparison never flatters molmesh), vertex
// counts and the angle range of the result.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <exception>
#include <string>
#include <vector>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

// libgamer's headers define min/max macros and need <cstdio> types first.
#include <gamer/biom.h>
#undef min
#undef max

namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

molmesh::SurfaceMesh to_molmesh(const ::SurfaceMesh* mesh) {
  molmesh::SurfaceMesh out;
  for (int i = 0; i < mesh->nv; ++i)
    out.points.emplace_back(mesh->vertex[i].x, mesh->vertex[i].y, mesh->vertex[i].z);
  for (int f = 0; f < mesh->nf; ++f)
    out.triangles.push_back({mesh->face[f].a, mesh->face[f].b, mesh->face[f].c});
  return out;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 2) {
    std::fprintf(stderr, "usage: gamer1_surface INPUT.pqr [OUT.off]\n");
    return 2;
  }
  auto start = Clock::now();
  const molmesh::Atoms atoms = molmesh::read_atoms(argv[1]);
  molmesh::BlurOptions blur;  // the paper's: B = -0.5, 0.5 Å, isovalue 1
  const molmesh::Grid grid = molmesh::blur_atoms(atoms, blur);
  const double blur_seconds = since(start);

  // GAMer's marching cubes takes floats, x fastest, and returns grid coordinates.
  std::vector<float> data(grid.values.begin(), grid.values.end());
  // GAMer is single-threaded, so process CPU time from here on is its CPU time (the honest
  // measure on a shared machine, where wall time depends on the load).
  const std::clock_t cpu_start = std::clock();
  start = Clock::now();
  SPNT* holes = nullptr;
  ::SurfaceMesh* mesh =
      SurfaceMesh_marchingCube(grid.dims[0], grid.dims[1], grid.dims[2], data.data(),
                               static_cast<float>(blur.isovalue), &holes);
  const double mc_seconds = since(start);
  for (int i = 0; i < mesh->nv; ++i) {
    mesh->vertex[i].x = static_cast<float>(grid.origin.x() + mesh->vertex[i].x * grid.spacing.x());
    mesh->vertex[i].y = static_cast<float>(grid.origin.y() + mesh->vertex[i].y * grid.spacing.y());
    mesh->vertex[i].z = static_cast<float>(grid.origin.z() + mesh->vertex[i].z * grid.spacing.z());
  }
  const int raw_vertices = mesh->nv;

  start = Clock::now();
  SurfaceMesh_createNeighborlist(mesh);
  SurfaceMesh_smooth(mesh, 10, 160, 15, false);
  SurfaceMesh_coarse(mesh, 0.2f, 1.0f, 1.0f, 0.5f);
  for (int round = 1; round <= 30; ++round)
    if (SurfaceMesh_smooth(mesh, 20, 140, 1, true)) break;
  SurfaceMesh_normalSmooth(mesh);
  const double processing_seconds = since(start);
  const double gamer_cpu_seconds =
      static_cast<double>(std::clock() - cpu_start) / static_cast<double>(CLOCKS_PER_SEC);

  if (argc > 2) SurfaceMesh_writeOFF(mesh, argv[2]);
  const molmesh::SurfaceStats stats = molmesh::compute_surface_stats(to_molmesh(mesh));
  std::printf(
      "{\"blur_seconds\": %.3f, \"marching_cubes_seconds\": %.3f, \"processing_seconds\": %.3f, "
      "\"gamer_seconds\": %.3f, \"gamer_cpu_seconds\": %.3f, \"raw_vertices\": %d, \"vertices\": "
      "%d, \"min_angle\": %.2f, "
      "\"max_angle\": %.2f, \"in_40_80\": %.4f}\n",
      blur_seconds, mc_seconds, processing_seconds, mc_seconds + processing_seconds,
      gamer_cpu_seconds, raw_vertices, mesh->nv, stats.min_angle_deg, stats.max_angle_deg,
      stats.fraction_angles_40_80);
  SurfaceMesh_dtor(mesh);
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "gamer1_surface: %s\n", e.what());
  return 1;
}
