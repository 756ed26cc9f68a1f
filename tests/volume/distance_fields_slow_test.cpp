// Volumes and areas of the vdW, SAS and SES meshes of real molecules against references
// computed here by other means:
//   - volumes: counting the samples of a finer grid (0.2 Å) that lie inside, where "inside"
//     is decided directly from the atoms: in some ball (vdW, SAS), or in the SAS but farther
//     than the probe radius from every exposed point of the SAS boundary (SES), with that
//     boundary sampled by golden-spiral points every ~0.15 Å (so the probe balls around
//     them cover the solvent to within s^2 / 8p ~ 0.002 Å);
//   - areas (vdW, SAS): Shrake-Rupley, the exposed fraction of 4000 spiral points per sphere.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_pipeline.hpp"

namespace molmesh {
namespace {

constexpr double kPi = std::numbers::pi;

std::vector<Vec3> spiral(int n) {
  std::vector<Vec3> points;
  const double golden = kPi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (i + 0.5) * 2.0 / n;
    const double r = std::sqrt(1.0 - z * z);
    points.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return points;
}

struct Balls {
  std::vector<Vec3> c;
  std::vector<double> R;
  std::vector<std::vector<std::size_t>> neighbours;  // balls whose sphere meets ball i's
  // Whether p, a point on sphere i, is inside another ball.
  bool buried(const Vec3& p, std::size_t i) const {
    for (std::size_t j : neighbours[i])
      if ((p - c[j]).squaredNorm() < R[j] * R[j]) return true;
    return false;
  }
};

Balls balls_of(const Atoms& atoms, double grow) {
  Balls b;
  for (const Atom& a : atoms)
    if (a.radius > 0.0) {
      b.c.push_back(a.center);
      b.R.push_back(a.radius + grow);
    }
  b.neighbours.resize(b.c.size());
  for (std::size_t i = 0; i < b.c.size(); ++i)
    for (std::size_t j = i + 1; j < b.c.size(); ++j)
      if ((b.c[i] - b.c[j]).norm() < b.R[i] + b.R[j]) {
        b.neighbours[i].push_back(j);
        b.neighbours[j].push_back(i);
      }
  return b;
}

double shrake_rupley_area(const Balls& b) {
  const std::vector<Vec3> unit = spiral(4000);
  double area = 0.0;
  for (std::size_t i = 0; i < b.c.size(); ++i) {
    int exposed = 0;
    for (const Vec3& u : unit) exposed += !b.buried(b.c[i] + b.R[i] * u, i);
    area += 4.0 * kPi * b.R[i] * b.R[i] * exposed / double(unit.size());
  }
  return area;
}

// Counting grid over the SAS box (+1 Å): one char per sample.
struct CountGrid {
  Vec3 lo;
  double h;
  int n[3];
  std::vector<char> mark;
  CountGrid(const Balls& sas, double spacing) : h(spacing) {
    lo = Vec3::Constant(1e30);
    Vec3 hi = -lo;
    for (std::size_t i = 0; i < sas.c.size(); ++i) {
      lo = lo.cwiseMin(sas.c[i] - Vec3::Constant(sas.R[i] + 1.0));
      hi = hi.cwiseMax(sas.c[i] + Vec3::Constant(sas.R[i] + 1.0));
    }
    for (int a = 0; a < 3; ++a) n[a] = int((hi[a] - lo[a]) / h) + 1;
    mark.assign(std::size_t(n[0]) * n[1] * n[2], 0);
  }
  // Sets `bit` on every sample within r of c.
  void paint(const Vec3& c, double r, char bit) {
    int a0[3], a1[3];
    for (int a = 0; a < 3; ++a) {
      a0[a] = std::max(0, int(std::ceil((c[a] - r - lo[a]) / h)));
      a1[a] = std::min(n[a] - 1, int(std::floor((c[a] + r - lo[a]) / h)));
    }
    for (int k = a0[2]; k <= a1[2]; ++k)
      for (int j = a0[1]; j <= a1[1]; ++j)
        for (int i = a0[0]; i <= a1[0]; ++i) {
          const Vec3 x = lo + h * Vec3(i, j, k);
          if ((x - c).squaredNorm() < r * r)
            mark[i + std::size_t(n[0]) * (j + std::size_t(n[1]) * k)] |= bit;
        }
  }
  double volume(char all, char none) const {
    std::size_t count = 0;
    for (char m : mark) count += (m & all) == all && (m & none) == 0;
    return count * h * h * h;
  }
};

SurfaceStats mesh_stats(const Atoms& atoms, SurfaceKind kind, bool raw) {
  SurfacePipelineOptions options;
  options.surface = kind;
  options.raw = raw;
  return compute_surface_stats(surface_from_atoms(atoms, options).surface);
}

class MoleculeSurfaces : public ::testing::TestWithParam<std::string> {};

TEST_P(MoleculeSurfaces, VolumesAndAreasWithinOnePercentOfIndependentEstimates) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + GetParam());
  const double probe = 1.4;
  const Balls vdw = balls_of(atoms, 0.0), sas = balls_of(atoms, probe);
  CountGrid grid(sas, 0.2);
  constexpr char kVdw = 1, kSas = 2, kSolvent = 4;
  for (std::size_t i = 0; i < vdw.c.size(); ++i) {
    grid.paint(vdw.c[i], vdw.R[i], kVdw);
    grid.paint(sas.c[i], sas.R[i], kSas);
  }
  // Probe balls around the exposed SAS boundary: the solvent inside the SAS.
  for (std::size_t i = 0; i < sas.c.size(); ++i) {
    const int n = int(4.0 * kPi * sas.R[i] * sas.R[i] / (0.15 * 0.15));
    for (const Vec3& u : spiral(n)) {
      const Vec3 p = sas.c[i] + sas.R[i] * u;
      if (!sas.buried(p, i)) grid.paint(p, probe, kSolvent);
    }
  }
  const double ref_vdw = grid.volume(kVdw, 0), ref_sas = grid.volume(kSas, 0);
  const double ref_ses = grid.volume(kSas, kSolvent);
  const double area_vdw = shrake_rupley_area(vdw), area_sas = shrake_rupley_area(sas);
  for (bool raw : {true, false}) {
    const SurfaceStats v = mesh_stats(atoms, SurfaceKind::kVdw, raw);
    const SurfaceStats s = mesh_stats(atoms, SurfaceKind::kSas, raw);
    const SurfaceStats e = mesh_stats(atoms, SurfaceKind::kSes, raw);
    const std::string what = GetParam() + (raw ? " raw" : " processed");
    std::printf(
        "%s: vdW %.1f/%.1f A^3 %.1f/%.1f A^2, SAS %.1f/%.1f A^3 %.1f/%.1f A^2, "
        "SES %.1f/%.1f A^3 (mesh/reference)\n",
        what.c_str(), v.volume, ref_vdw, v.area, area_vdw, s.volume, ref_sas, s.area, area_sas,
        e.volume, ref_ses);
    EXPECT_NEAR(v.volume / ref_vdw, 1.0, 0.01) << what;
    EXPECT_NEAR(v.area / area_vdw, 1.0, 0.01) << what;
    EXPECT_NEAR(s.volume / ref_sas, 1.0, 0.01) << what;
    EXPECT_NEAR(s.area / area_sas, 1.0, 0.01) << what;
    EXPECT_NEAR(e.volume / ref_ses, 1.0, 0.01) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(TestData, MoleculeSurfaces, ::testing::Values("1a1p.pqr", "fas2.pqr"),
                         [](const auto& info) { return info.param.substr(0, 4); });

}  // namespace
}  // namespace molmesh
