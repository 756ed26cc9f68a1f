// Steady-state Smoluchowski rate constants on a shell mesh against the analytic answers:
// an absorbing sphere in a finite outer sphere, with and without a Coulomb potential.
#include "solvers/physics/smoluchowski.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "molmesh/core/error.hpp"
#include "solvers/physics/units.hpp"
#include "solvers/shell_mesh.hpp"

namespace molmesh::solvers {
namespace {

constexpr double kR = 10.0, kRb = 100.0, kD = 1e-5;

const test::ShellHierarchy& sphere_hierarchy() {
  static const test::ShellHierarchy h = test::make_shell_hierarchy(
      {.inner_radius = kR, .outer_radius = kRb, .subdivisions = 4, .radial_layers = 24}, 4);
  return h;
}

double smoluchowski_limit_per_molar_per_s() {
  const double d = kD * units::kSquareAngstromPerSquareCm;
  return units::rate_to_per_molar_per_second(4.0 * std::numbers::pi * d * kR / (1.0 - kR / kRb));
}

TEST(Smoluchowski, AbsorbingSphereMatchesTheAnalyticRate) {
  const auto& h = sphere_hierarchy();
  SmoluchowskiOptions options;
  options.diffusion_cm2_per_s = kD;
  const auto result = solve_smoluchowski(h.meshes[0].mesh, {}, h.prolongations, options);
  const double expected = smoluchowski_limit_per_molar_per_s();
  EXPECT_NEAR(expected, 8.4085e9, 0.0005e9);
  std::printf("k = %.5e M^-1 s^-1 (analytic %.5e, error %+.3f %%), %d CG iterations\n",
              result.rate_constant_per_molar_per_s, expected,
              100.0 * (result.rate_constant_per_molar_per_s / expected - 1.0),
              result.solve.iterations);
  EXPECT_TRUE(result.solve.converged);
  EXPECT_NEAR(result.rate_constant_per_molar_per_s / expected, 1.0, 0.01);
  // The concentration is 0 on the sphere, 1 at the bulk boundary, and close to the
  // analytic profile (1 - R/r)/(1 - R/Rb) in between.
  const TetMesh& m = h.meshes[0].mesh;
  double worst = 0.0;
  for (std::size_t v = 0; v < m.points.size(); ++v) {
    const double r = m.points[v].norm();
    const double exact = (1.0 - kR / r) / (1.0 - kR / kRb);
    worst = std::max(worst, std::abs(result.concentration[static_cast<Eigen::Index>(v)] - exact));
  }
  EXPECT_LT(worst, 0.01);
}

TEST(Smoluchowski, CoulombAttractionMatchesTheQuadratureRate) {
  const auto& h = sphere_hierarchy();
  const double a = -7.136;  // z1 z2 = -1, Å
  const TetMesh& m = h.meshes[0].mesh;
  std::vector<double> beta_w(m.points.size());
  for (std::size_t v = 0; v < m.points.size(); ++v) beta_w[v] = a / m.points[v].norm();
  SmoluchowskiOptions options;
  options.diffusion_cm2_per_s = kD;
  const auto result = solve_smoluchowski(m, beta_w, h.prolongations, options);
  // Reference: k = 4 pi D / int_R^Rb exp(beta W(r)) / r^2 dr, by composite Simpson in
  // u = 1/r (smooth integrand exp(a u)), checked against the closed form.
  const int n = 2000;
  const double u0 = 1.0 / kRb, u1 = 1.0 / kR, du = (u1 - u0) / n;
  double integral = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    integral += w * std::exp(a * (u0 + i * du));
  }
  integral *= du / 3.0;
  EXPECT_NEAR(integral, (std::exp(a / kR) - std::exp(a / kRb)) / a, 1e-10);
  const double d = kD * units::kSquareAngstromPerSquareCm;
  const double expected =
      units::rate_to_per_molar_per_second(4.0 * std::numbers::pi * d / integral);
  const double basic = units::rate_to_per_molar_per_second(4.0 * std::numbers::pi * d * kR);
  std::printf("k/(4 pi D R) = %.5f (analytic %.5f), %d CG iterations\n",
              result.rate_constant_per_molar_per_s / basic, expected / basic,
              result.solve.iterations);
  EXPECT_NEAR(expected / basic, 1.61722, 0.00005);
  EXPECT_TRUE(result.solve.converged);
  EXPECT_NEAR(result.rate_constant_per_molar_per_s / expected, 1.0, 0.02);
}

TEST(Smoluchowski, ActiveSitePatchAbsorbsLessThanTheWholeSphere) {
  // Mark a cap of the sphere as active site: the rate must be below the full sphere's and
  // above the rate 4 D a' of a disk of the cap's rim radius a' in an absorbing-free plane
  // (a cap on a sphere draws from a wider solid angle than a disk in a wall).
  auto shell = test::make_shell_mesh(
      {.inner_radius = kR, .outer_radius = kRb, .subdivisions = 3, .radial_layers = 12});
  TetMesh& m = shell.mesh;
  int patch = 0;
  for (std::size_t f = 0; f < m.boundary_faces.size(); ++f) {
    if (m.boundary_face_markers[f] != markers::kMolecularSurface) continue;
    bool inside = true;
    for (int v : m.boundary_faces[f]) {
      inside = inside && m.points[static_cast<std::size_t>(v)].z() > 0.9 * kR;
    }
    if (inside) {
      m.boundary_face_markers[f] = markers::kActiveSite;
      ++patch;
    }
  }
  ASSERT_GT(patch, 0);
  SmoluchowskiOptions options;
  options.diffusion_cm2_per_s = kD;
  options.absorbing_markers = {markers::kActiveSite};
  const auto result = solve_smoluchowski(m, {}, {}, options);
  const double full = smoluchowski_limit_per_molar_per_s();
  EXPECT_TRUE(result.solve.converged);
  const double rim = kR * std::sqrt(1.0 - 0.9 * 0.9);
  const double disk =
      units::rate_to_per_molar_per_second(4.0 * kD * units::kSquareAngstromPerSquareCm * rim);
  std::printf("cap rate %.4e, disk estimate %.4e, full sphere %.4e\n",
              result.rate_constant_per_molar_per_s, disk, full);
  EXPECT_GT(result.rate_constant_per_molar_per_s, disk);
  EXPECT_LT(result.rate_constant_per_molar_per_s, 0.9 * full);

  options.absorbing_markers = {99};
  EXPECT_THROW(solve_smoluchowski(m, {}, {}, options), Error);
}

}  // namespace
}  // namespace molmesh::solvers
