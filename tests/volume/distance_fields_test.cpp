// The vdW / SAS / SES distance fields against references computed here independently:
// brute-force distance transforms, and closed-form volumes and areas of one and two atoms
// (union of balls: spherical caps; SES of two atoms: a solid of revolution whose profile is
// the two spheres joined by the probe's re-entrant arc, integrated numerically).
#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "molmesh/volume/ball_union.hpp"
#include "molmesh/volume/distance_transform.hpp"
#include "molmesh/volume/ses_field.hpp"
#include "support/atoms.hpp"

namespace molmesh {
namespace {

constexpr double kPi = std::numbers::pi;

using testing::make_atom;

TEST(DistanceTransform, MatchesBruteForce) {
  const std::array<int, 3> dims{13, 11, 9};
  const Vec3 spacing(0.5, 0.7, 0.3);
  const std::size_t size = 13 * 11 * 9;
  std::mt19937 rng(7);
  std::vector<char> sites(size, 0);
  for (std::size_t n = 0; n < size; ++n) sites[n] = (rng() % 23) == 0;
  const DistanceTransform edt = euclidean_distance_transform(sites, dims, spacing);
  auto position = [&](std::size_t n) {
    return Vec3(double(n % 13) * spacing.x(), double((n / 13) % 11) * spacing.y(),
                double(n / (13 * 11)) * spacing.z());
  };
  for (std::size_t n = 0; n < size; ++n) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t m = 0; m < size; ++m)
      if (sites[m]) best = std::min(best, (position(n) - position(m)).squaredNorm());
    ASSERT_NEAR(edt.squared_distance[n], best, 1e-9) << n;
    ASSERT_GE(edt.nearest[n], 0);
    ASSERT_TRUE(sites[static_cast<std::size_t>(edt.nearest[n])]);
    ASSERT_NEAR((position(n) - position(static_cast<std::size_t>(edt.nearest[n]))).squaredNorm(),
                best, 1e-9);
  }
}

TEST(DistanceTransform, NoSitesStaysInfinite) {
  const DistanceTransform edt =
      euclidean_distance_transform(std::vector<char>(24, 0), {2, 3, 4}, Vec3::Ones());
  for (double d : edt.squared_distance) EXPECT_TRUE(std::isinf(d));
}

TEST(BallUnion, IsMinusTheDistanceNearTheBalls) {
  const Atoms atoms{make_atom(0.1, -0.2, 0.3, 1.7), make_atom(1.9, 0.4, -0.1, 1.2)};
  const Grid grid = ball_union_field(atoms, 0.5, 0.25);
  for (int k = 0; k < grid.dims[2]; ++k)
    for (int j = 0; j < grid.dims[1]; ++j)
      for (int i = 0; i < grid.dims[0]; ++i) {
        const Vec3 x = grid.position(i, j, k);
        double u = -std::numeric_limits<double>::infinity();
        for (const Atom& a : atoms) u = std::max(u, a.radius + 0.5 - (x - a.center).norm());
        if (u >= -0.5)
          ASSERT_NEAR(grid.at(i, j, k), u, 1e-12);
        else
          ASSERT_LE(grid.at(i, j, k), -0.5 + 1e-12);
      }
}

// Union of two balls: two spheres minus the caps inside each other.
struct UnionReference {
  double volume = 0.0;
  double area = 0.0;
};
UnionReference two_ball_union(double r1, double r2, double d) {
  const double a = (d * d + r1 * r1 - r2 * r2) / (2.0 * d);  // centre 1 -> intersection plane
  const double h1 = r1 - a;                                  // cap of ball 1 inside ball 2
  const double h2 = r2 - (d - a);
  const double lens = kPi * (r1 + r2 - d) * (r1 + r2 - d) *
                      (d * d + 2.0 * d * (r1 + r2) - 3.0 * (r1 - r2) * (r1 - r2)) / (12.0 * d);
  return {4.0 / 3.0 * kPi * (r1 * r1 * r1 + r2 * r2 * r2) - lens,
          4.0 * kPi * (r1 * r1 + r2 * r2) - 2.0 * kPi * (r1 * h1 + r2 * h2)};
}

// SES of two atoms on the z axis (centres 0 and d): a solid of revolution. In the meridian
// plane the probe (radius p) touching both atoms sits at (z0, rho0); between its contact
// points the profile is the probe's arc rho = rho0 - sqrt(p^2 - (z - z0)^2), outside them the
// atoms' spheres. Volume and area by the midpoint rule on a million slices.
UnionReference two_atom_ses(double r1, double r2, double d, double p) {
  const double R1 = r1 + p, R2 = r2 + p;
  const double z0 = (d * d + R1 * R1 - R2 * R2) / (2.0 * d);
  const double rho0 = std::sqrt(R1 * R1 - z0 * z0);
  const double t1 = z0 * r1 / R1;            // contact point on atom 1 (z)
  const double t2 = d + (z0 - d) * r2 / R2;  // contact point on atom 2 (z)
  const int n = 1000000;
  const double lo = -r1, hi = d + r2, dz = (hi - lo) / n;
  UnionReference ref;
  for (int s = 0; s < n; ++s) {
    const double z = lo + (s + 0.5) * dz;
    double rho, ds;  // profile radius and arc length factor sqrt(1 + rho'^2)
    if (z < t1) {
      rho = std::sqrt(r1 * r1 - z * z);
      ds = r1 / rho;
    } else if (z > t2) {
      rho = std::sqrt(r2 * r2 - (z - d) * (z - d));
      ds = r2 / rho;
    } else {
      const double s2 = std::sqrt(p * p - (z - z0) * (z - z0));
      rho = rho0 - s2;
      ds = p / s2;
    }
    ref.volume += kPi * rho * rho * dz;
    ref.area += 2.0 * kPi * rho * ds * dz;
  }
  return ref;
}

SurfaceStats contour(const Grid& grid) { return compute_surface_stats(marching_cubes(grid, 0.0)); }

TEST(BallUnion, OneAndTwoAtomsMatchClosedForm) {
  // Marching cubes' chords cost area as (h / r)^2: 1.4 % at 0.2 Å on these atoms.
  const double h = 0.1;
  {
    const SurfaceStats s = contour(ball_union_field({make_atom(0.3, 0.1, -0.2, 1.8)}, 0.0, h));
    EXPECT_NEAR(s.volume / (4.0 / 3.0 * kPi * std::pow(1.8, 3)), 1.0, 0.01);
    EXPECT_NEAR(s.area / (4.0 * kPi * 1.8 * 1.8), 1.0, 0.01);
    EXPECT_TRUE(s.closed && s.manifold);
  }
  for (double probe : {0.0, 1.4}) {
    const Atoms atoms{make_atom(0.0, 0.0, 0.0, 1.6), make_atom(0.0, 0.0, 2.8, 1.8)};
    const SurfaceStats s = contour(ball_union_field(atoms, probe, h));
    const UnionReference ref = two_ball_union(1.6 + probe, 1.8 + probe, 2.8);
    EXPECT_NEAR(s.volume / ref.volume, 1.0, 0.01) << "probe " << probe;
    EXPECT_NEAR(s.area / ref.area, 1.0, 0.01) << "probe " << probe;
    EXPECT_EQ(s.components, 1);
  }
}

TEST(SesField, TwoAtomsMatchTheSolidOfRevolution) {
  // Tilted off the grid axes so no symmetry of the grid helps.
  const Vec3 c1(0.13, -0.31, 0.07);
  const Vec3 axis = Vec3(0.3, 0.5, 0.8).normalized();
  for (double d : {2.8, 3.6}) {
    const Atoms atoms{
        make_atom(c1.x(), c1.y(), c1.z(), 1.6),
        make_atom(c1.x() + d * axis.x(), c1.y() + d * axis.y(), c1.z() + d * axis.z(), 1.8)};
    const UnionReference ref = two_atom_ses(1.6, 1.8, d, 1.4);
    // At 0.5 Å the chords of marching cubes on these 1.6 Å atoms cost 3.7 % of the volume
    // (molecules, with less curvature per area, stay within 1 %: the slow test).
    for (double h : {0.15, 0.25}) {
      const SurfaceStats s = contour(ses_field(atoms, 1.4, h));
      EXPECT_NEAR(s.volume / ref.volume, 1.0, 0.01) << "d " << d << " h " << h;
      EXPECT_NEAR(s.area / ref.area, 1.0, 0.01) << "d " << d << " h " << h;
      EXPECT_TRUE(s.closed && s.manifold);
      EXPECT_EQ(s.components, 1);
    }
  }
}

TEST(SesField, ZeroProbeIsTheVdwField) {
  const Atoms atoms{make_atom(0, 0, 0, 1.6), make_atom(0.5, 2.1, 0.3, 1.2),
                    make_atom(-1.4, 1.0, 1.1, 1.5)};
  const Grid ses = ses_field(atoms, 0.0, 0.3);
  const Grid vdw = ball_union_field(atoms, 0.0, 0.3);
  ASSERT_EQ(ses.dims, vdw.dims);
  // Same zero set; inside the balls the SES field is the distance to the union's boundary,
  // the vdW field the largest depth in one ball, so interpolated crossings differ slightly.
  const SurfaceStats a = contour(ses), b = contour(vdw);
  EXPECT_NEAR(a.volume, b.volume, 1e-3 * b.volume);
}

TEST(SesField, ProbeFillsTheGrooveAndIndependentOfThreads) {
  Atoms atoms;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> pos(-4.0, 4.0), rad(1.0, 2.0);
  for (int i = 0; i < 40; ++i) atoms.push_back(make_atom(pos(rng), pos(rng), pos(rng), rad(rng)));
  Grid one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = ses_field(atoms, 1.4, 0.4);
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = ses_field(atoms, 1.4, 0.4);
  }
  EXPECT_EQ(one.values, two.values);
  // vdW inside SES inside SAS.
  const double v_ses = contour(one).volume;
  const double v_vdw = contour(ball_union_field(atoms, 0.0, 0.4)).volume;
  const double v_sas = contour(ball_union_field(atoms, 1.4, 0.4)).volume;
  EXPECT_LT(v_vdw, v_ses);
  EXPECT_LT(v_ses, v_sas);
}

}  // namespace
}  // namespace molmesh
