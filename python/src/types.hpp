#pragma once
// The Python-visible objects. Each holds the library's plain type through a shared_ptr to
// const (levels of a hierarchy alias into the Hierarchy they belong to), so arrays are
// read-only numpy views with no copy, and `report`/`raw` carry what the stage measured.
// These structs are only created and destroyed by Python, with the GIL held, so they may
// hold Python objects.
#include <pybind11/pybind11.h>

#include <memory>
#include <optional>
#include <string>

#include "molmesh/atoms/atom.hpp"
#include "molmesh/hierarchy/hierarchy.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/pipeline/surface_source.hpp"
#include "molmesh/surface/surface_mesh.hpp"
#include "molmesh/tetmesh/tet_mesh.hpp"
#include "molmesh/volume/grid.hpp"

namespace molmesh::python {

namespace py = pybind11;

// Where read_atoms() read the atoms from (a hierarchy built from them records it as the
// CLI does: input name, checksum, the read options among its parameters).
struct AtomsSource {
  std::string name;      // the file name, without its folder
  std::string checksum;  // SHA-256 (hex) of the file's bytes
  AtomReadOptions options;
};

struct PyAtoms {
  std::shared_ptr<const Atoms> atoms;
  std::optional<AtomsSource> source;  // nullopt: from arrays
};

// What the parameter writers record of a surface made from `atoms` with `options`: the
// options, and how the atoms were read when they came from a file (as the CLI records).
inline SurfaceSource surface_source(const PyAtoms& atoms, const SurfacePipelineOptions& options) {
  SurfaceSource source{std::nullopt, options};
  if (atoms.source) source.atoms = atoms.source->options;
  return source;
}

struct PySurface {
  std::shared_ptr<const SurfaceMesh> mesh;
  py::object raw = py::none();     // surface(): marching cubes output; improve(): repaired input
  py::object report = py::none();  // dict: stages, timings, ... of the stage that made it
};

struct PyTetMesh {
  std::shared_ptr<const TetMesh> mesh;
  py::object report = py::none();
};

struct PyVolume {
  std::shared_ptr<const Grid> grid;
};

struct PyHierarchy {
  std::shared_ptr<const Hierarchy> hierarchy;
  py::object report = py::none();
};

}  // namespace molmesh::python
