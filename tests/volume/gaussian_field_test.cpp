// GaussianField: Eq. 1 at any point, checked against blur_atoms' samples and its own
// finite differences on a real molecule.
#include "molmesh/volume/gaussian_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "molmesh/core/error.hpp"
#include "molmesh/io/read_atoms.hpp"

namespace molmesh {
namespace {

Atoms atoms_of(const std::string& name) {
  return read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + name);
}

TEST(GaussianField, EqualsTheBlurredGridAtItsSamples) {
  const Atoms atoms = atoms_of("1a1p.pqr");
  BlurOptions blur;
  blur.spacing = 0.5;
  const Grid grid = blur_atoms(atoms, blur);
  const GaussianField field(atoms, blur);
  double largest = 0.0;
  int checked = 0;
  for (int k = 0; k < grid.dims[2]; k += 3)
    for (int j = 0; j < grid.dims[1]; j += 5)
      for (int i = 0; i < grid.dims[0]; i += 7) {
        const double expected = grid.at(i, j, k);
        EXPECT_NEAR(field.value(grid.position(i, j, k)), expected, 1e-12 * (1.0 + expected));
        largest = std::max(largest, expected);
        ++checked;
      }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(largest, blur.isovalue);  // the samples reach inside the molecule
}

TEST(GaussianField, GradientMatchesFiniteDifferences) {
  const Atoms atoms = atoms_of("fas2.pqr");
  BlurOptions blur;
  blur.blobbyness = -2.5;
  const GaussianField field(atoms, blur);
  int checked = 0;
  for (std::size_t n = 0; n < atoms.size(); n += 37) {
    // Points around the atom's surface, where the level set lies.
    const Vec3 p = atoms[n].center + Vec3(0.8, -0.5, 0.6) * atoms[n].radius;
    Vec3 g;
    const double f = field.value(p, &g);
    EXPECT_EQ(f, field.value(p));
    const double e = 1e-5;
    for (int a = 0; a < 3; ++a) {
      Vec3 step = Vec3::Zero();
      step[a] = e;
      const double fd = (field.value(p + step) - field.value(p - step)) / (2 * e);
      EXPECT_NEAR(g[a], fd, 1e-6 * (1.0 + g.norm())) << n << " axis " << a;
    }
    ++checked;
  }
  EXPECT_GT(checked, 10);
  EXPECT_EQ(field.value(Vec3(1e4, 0, 0)), 0.0);  // far from every atom
}

TEST(GaussianField, RefusesWhatBlurAtomsRefuses) {
  const Atoms atoms = atoms_of("fas2.pqr");
  BlurOptions blur;
  blur.blobbyness = 0.5;
  EXPECT_THROW(GaussianField(atoms, blur), Error);
  blur.blobbyness = -0.5;
  blur.truncation = 2.0;
  EXPECT_THROW(GaussianField(atoms, blur), Error);
  EXPECT_THROW(GaussianField(Atoms{}, BlurOptions{}), Error);
}

}  // namespace
}  // namespace molmesh
