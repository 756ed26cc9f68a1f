#include "molmesh/volume/gaussian_blur.hpp"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>

#include "molmesh/core/error.hpp"
#include "support/atoms.hpp"

namespace molmesh {
namespace {

using testing::make_atom;

double kernel(const Atom& a, double b, const Vec3& x) {
  return std::exp(b * ((x - a.center).squaredNorm() / (a.radius * a.radius) - 1.0));
}

Atoms random_cluster(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> pos(-6.0, 6.0);
  std::uniform_real_distribution<double> rad(1.0, 2.0);
  Atoms atoms;
  for (int i = 0; i < n; ++i) atoms.push_back(make_atom(pos(rng), pos(rng), pos(rng), rad(rng)));
  return atoms;
}

TEST(KernelRadius, SolvesForTheKernelValue) {
  EXPECT_DOUBLE_EQ(kernel_radius(1.7, -0.5, 1.0), 1.7);
  for (double b : {-0.3, -0.5, -2.5})
    for (double v : {1e-4, 0.1, 0.9, 1.2}) {
      const double s = kernel_radius(1.5, b, v);
      ASSERT_GT(s, 0.0);
      EXPECT_NEAR(std::exp(b * (s * s / 2.25 - 1.0)), v, 1e-12 * v + 1e-15);
    }
  EXPECT_EQ(kernel_radius(1.5, -0.5, 2.0), 0.0);  // above the peak exp(0.5)
  EXPECT_EQ(kernel_radius(0.0, -0.5, 1.0), 0.0);
}

// Inside the cutoff sphere the samples are Eq. 1 to rounding; outside they are exactly 0.
TEST(GaussianBlur, LoneAtomMatchesEquationOneInsideTheCutoff) {
  const Atom atom = make_atom(0.37, -1.21, 2.05, 1.6);
  BlurOptions options;
  const Grid g = blur_atoms({atom}, options);
  const double cutoff = kernel_radius(1.6, -0.5, options.truncation * options.isovalue);
  int inside = 0;
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i) {
        const Vec3 x = g.position(i, j, k);
        const double d = (x - atom.center).norm();
        if (d <= cutoff * (1 - 1e-9)) {
          ++inside;
          ASSERT_NEAR(g.at(i, j, k), kernel(atom, -0.5, x), 1e-14);
        } else if (d > cutoff * (1 + 1e-9)) {
          ASSERT_EQ(g.at(i, j, k), 0.0);
        }
      }
  EXPECT_GT(inside, 1000);
  // The isosurface F = 1 (distance r) is at least margin_cells cells from every face.
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_GE(atom.center[axis] - 1.6 - g.origin[axis], options.margin_cells * options.spacing);
    EXPECT_GE(g.origin[axis] + (g.dims[axis] - 1) * options.spacing - atom.center[axis] - 1.6,
              options.margin_cells * options.spacing);
  }
}

// The only error is the truncation: per atom below truncation * isovalue at each sample.
TEST(GaussianBlur, ErrorIsBoundedByTruncation) {
  const Atoms atoms = random_cluster(60, 11);
  BlurOptions options;
  options.spacing = 0.7;
  const Grid g = blur_atoms(atoms, options);
  const double per_atom = options.truncation * options.isovalue;
  double worst = 0.0;
  for (int k = 0; k < g.dims[2]; k += 2)
    for (int j = 0; j < g.dims[1]; j += 2)
      for (int i = 0; i < g.dims[0]; i += 2) {
        const Vec3 x = g.position(i, j, k);
        double exact = 0.0, bound = 0.0;
        for (const Atom& a : atoms) {
          const double v = kernel(a, -0.5, x);
          exact += v;
          if (v < per_atom) bound += v;
        }
        const double err = std::abs(g.at(i, j, k) - exact);
        ASSERT_LE(err, bound + 1e-12);
        worst = std::max(worst, err);
      }
  EXPECT_LT(worst, 60 * per_atom);
}

TEST(GaussianBlur, ZeroRadiusAtomsAddNothingAndPerAtomBlobbynessIsUsed) {
  Atoms atoms = random_cluster(20, 3);
  const Grid base = blur_atoms(atoms, {});
  Atoms with_zero = atoms;
  with_zero.insert(with_zero.begin() + 5, make_atom(0.0, 0.0, 0.0, 0.0));
  with_zero.push_back(make_atom(1.0, 2.0, 3.0, 0.0));
  const Grid same = blur_atoms(with_zero, {});
  EXPECT_EQ(same.dims, base.dims);
  EXPECT_EQ(same.values, base.values);

  Atom sharp = make_atom(0, 0, 0, 1.5);
  sharp.blobbyness = -2.5;
  const Grid g = blur_atoms({sharp}, {});
  const Vec3 x = g.position(g.dims[0] / 2 + 2, g.dims[1] / 2, g.dims[2] / 2);
  EXPECT_NEAR(g.at(g.dims[0] / 2 + 2, g.dims[1] / 2, g.dims[2] / 2), kernel(sharp, -2.5, x), 1e-14);
}

// Many overlapping tails reach the isovalue beyond any lone atom's sphere: the grid grows
// until its boundary is outside.
TEST(GaussianBlur, BoundaryIsAlwaysOutside) {
  Atoms atoms;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      for (int k = 0; k < 5; ++k) atoms.push_back(make_atom(1.0 * i, 1.0 * j, 1.0 * k, 1.0));
  BlurOptions options;
  options.isovalue = 0.3;
  options.margin_cells = 0;
  const Grid g = blur_atoms(atoms, options);
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        if (i == 0 || j == 0 || k == 0 || i == g.dims[0] - 1 || j == g.dims[1] - 1 ||
            k == g.dims[2] - 1) {
          ASSERT_LT(g.at(i, j, k), options.isovalue);
        }
}

TEST(GaussianBlur, SameValuesWithOneAndTwoThreads) {
  const Atoms atoms = random_cluster(300, 5);
  Grid one, two;
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 1);
    one = blur_atoms(atoms, {});
  }
  {
    tbb::global_control c(tbb::global_control::max_allowed_parallelism, 2);
    two = blur_atoms(atoms, {});
  }
  EXPECT_EQ(one.dims, two.dims);
  EXPECT_TRUE(one.values == two.values);
}

TEST(GaussianBlur, RejectsImpossibleRequests) {
  const Atoms atoms = random_cluster(3, 1);
  BlurOptions bad;
  bad.blobbyness = 0.5;
  EXPECT_THROW(blur_atoms(atoms, bad), Error);
  bad = {};
  bad.spacing = 0.0;
  EXPECT_THROW(blur_atoms(atoms, bad), Error);
  bad = {};
  bad.isovalue = -1.0;
  EXPECT_THROW(blur_atoms(atoms, bad), Error);
  EXPECT_THROW(blur_atoms({make_atom(0, 0, 0, 0.0)}, {}), Error);
  EXPECT_THROW(blur_atoms({}, {}), Error);
}

}  // namespace
}  // namespace molmesh
