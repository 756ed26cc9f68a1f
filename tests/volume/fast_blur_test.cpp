// The fast blur (§4.1) against the exact summation of the same Eq. 2 (blur_atoms with
// B_i = kappa r_i^2) on a real molecule, plus the properties the pipeline relies on.
#include "molmesh/volume/fast_blur.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>

#include "molmesh/core/error.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace molmesh {
namespace {

struct VolumeError {
  double max = 0.0;
  double mean = 0.0;
  double max_near_iso = 0.0;  // where the exact field is within [0.5, 2] x isovalue
};

VolumeError compare(const Grid& fast, const Grid& exact, double isovalue) {
  EXPECT_EQ(fast.dims, exact.dims);
  EXPECT_LT((fast.origin - exact.origin).norm(), 1e-12);
  VolumeError e;
  for (std::size_t i = 0; i < exact.values.size(); ++i) {
    const double d = std::abs(fast.values[i] - exact.values[i]);
    e.max = std::max(e.max, d);
    e.mean += d;
    if (exact.values[i] > 0.5 * isovalue && exact.values[i] < 2.0 * isovalue) {
      e.max_near_iso = std::max(e.max_near_iso, d);
    }
  }
  e.mean /= static_cast<double>(exact.values.size());
  return e;
}

TEST(FastBlur, MatchesTheExactSumOfEquation2On1a1p) {
  const Atoms atoms = read_atoms(MOLMESH_TEST_DATA_DIR "/1a1p.pqr");
  BlurOptions options;
  const double kappa = constant_decay_rate(atoms, options.blobbyness);
  EXPECT_LT(kappa, 0.0);
  const Grid exact = blur_atoms(with_constant_decay(atoms, kappa), options);
  const Grid trilinear = fast_blur(atoms, options, SplatMethod::kTrilinear);
  const Grid nearest = fast_blur(atoms, options, SplatMethod::kNearest);
  const VolumeError et = compare(trilinear, exact, options.isovalue);
  const VolumeError en = compare(nearest, exact, options.isovalue);
  // Measured (docs/inputs.md): trilinear max 0.064, mean 0.0031, near the isovalue 0.017.
  EXPECT_LT(et.max, 0.1);
  EXPECT_LT(et.mean, 0.006);
  EXPECT_LT(et.max_near_iso, 0.03);
  // Snapping atoms to nodes moves them by up to half a voxel: clearly worse, still bounded.
  EXPECT_GT(en.mean, 3.0 * et.mean);
  EXPECT_LT(en.max_near_iso, 0.7);
}

TEST(FastBlur, DericheIsMoreAccurateThanYoungVanVlietAndCompensationHelps) {
  const Atoms atoms = read_atoms(MOLMESH_TEST_DATA_DIR "/1a1p.pqr");
  BlurOptions options;
  const double kappa = constant_decay_rate(atoms, options.blobbyness);
  const Grid exact = blur_atoms(with_constant_decay(atoms, kappa), options);
  auto run = [&](RecursiveGaussianDesign design, bool compensate) {
    Grid g = exact;
    FastBlurOptions fast;
    fast.kappa = kappa;
    fast.design = design;
    fast.compensate_splat_width = compensate;
    fast_blur_onto(atoms, fast, g);
    return compare(g, exact, options.isovalue);
  };
  const auto deriche = run(RecursiveGaussianDesign::kDeriche4, true);
  const auto yvv = run(RecursiveGaussianDesign::kYoungVanVliet3, true);
  const auto uncompensated = run(RecursiveGaussianDesign::kDeriche4, false);
  EXPECT_LT(deriche.mean, 0.5 * yvv.mean);
  EXPECT_LT(deriche.mean, 0.5 * uncompensated.mean);
}

TEST(FastBlur, LoneAtomReachesTheIsovalueAtItsRadius) {
  Atoms atoms(1);
  atoms[0].center = Vec3(1.0, 2.0, 3.0);  // on a node of the 0.25 Å lattice
  atoms[0].radius = 1.5;
  BlurOptions options;
  options.spacing = 0.25;
  const Grid g = fast_blur(atoms, options);
  const Vec3 u = (atoms[0].center - g.origin) / options.spacing;
  const int i = static_cast<int>(std::lround(u.x()));
  const int j = static_cast<int>(std::lround(u.y()));
  const int k = static_cast<int>(std::lround(u.z()));
  // exp(kappa (d^2 - r^2)) with kappa = B / r^2: e^{-B} at the centre, 1 at d = r (6 cells).
  // An atom exactly on a node is the worst case of the splat-width compensation, which is
  // right on average over positions: measured 0.6% high.
  EXPECT_NEAR(g.at(i, j, k), std::exp(0.5), 0.01 * std::exp(0.5));
  EXPECT_NEAR(g.at(i + 6, j, k), 1.0, 0.01);
  EXPECT_NEAR(g.at(i, j - 6, k), 1.0, 0.01);
  EXPECT_NEAR(g.at(i, j, k + 6), 1.0, 0.01);
  EXPECT_NEAR(g.at(i + 6, j, k), g.at(i - 6, j, k), 1e-12);
}

TEST(FastBlur, ResultDoesNotDependOnTheThreadCount) {
  const Atoms atoms = read_atoms(MOLMESH_TEST_DATA_DIR "/1a1p.pqr");
  const Grid parallel = fast_blur(atoms, BlurOptions{});
  Grid serial;
  {
    tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    serial = fast_blur(atoms, BlurOptions{});
  }
  ASSERT_EQ(parallel.values.size(), serial.values.size());
  for (std::size_t i = 0; i < serial.values.size(); ++i) {
    ASSERT_EQ(parallel.values[i], serial.values[i]);
  }
}

TEST(FastBlur, RejectsWhatItCannotDo) {
  Atoms atoms(1);
  atoms[0].radius = 1.5;
  EXPECT_THROW(constant_decay_rate(atoms, 0.5), Error);
  Atoms none(1);
  EXPECT_THROW(constant_decay_rate(none, -0.5), Error);
  Grid grid;
  grid.dims = {5, 5, 5};
  grid.spacing = Vec3::Constant(0.5);
  FastBlurOptions fast;
  fast.kappa = -0.2;
  atoms[0].center = Vec3(10.0, 0.0, 0.0);  // outside the 2 Å box
  EXPECT_THROW(fast_blur_onto(atoms, fast, grid), Error);
  fast.kappa = 0.1;
  EXPECT_THROW(fast_blur_onto(atoms, fast, grid), Error);
  // sigma = sqrt(1 / (2 * 20)) = 0.16 Å is under half a 0.5 Å voxel.
  fast.kappa = -20.0;
  atoms[0].center = Vec3(1.0, 1.0, 1.0);
  EXPECT_THROW(fast_blur_onto(atoms, fast, grid), Error);
}

}  // namespace
}  // namespace molmesh
