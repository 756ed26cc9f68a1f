#pragma once
// Raw marching-cubes surfaces of the test molecules with the paper's parameters
// (B = -0.5, 0.5 Å spacing, isovalue 1), for the processing tests.
#include <string>

#include "molmesh/io/read_atoms.hpp"
#include "molmesh/surface/marching_cubes.hpp"
#include "molmesh/volume/gaussian_blur.hpp"

namespace molmesh::improve_test {

inline SurfaceMesh raw_surface(const std::string& name) {
  const Atoms atoms = read_atoms(std::string(MOLMESH_TEST_DATA_DIR) + "/" + name);
  BlurOptions blur;
  blur.spacing = 0.5;
  blur.blobbyness = -0.5;
  blur.isovalue = 1.0;
  return marching_cubes(blur_atoms(atoms, blur), 1.0);
}

}  // namespace molmesh::improve_test
