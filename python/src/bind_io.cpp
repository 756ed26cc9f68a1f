// Readers of every format the library reads (writers are the objects' write methods).
#include "bindings.hpp"
#include "casters.hpp"
#include "molmesh/io/msms.hpp"
#include "molmesh/io/sphere_list.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/volume_io.hpp"
#include "molmesh/io/volume_mesh_io.hpp"
#include "surface_objects.hpp"
#include "tables.hpp"
#include "tetmesh_objects.hpp"

namespace molmesh::python {

void bind_io(py::module_& m) {
  m.def(
      "read_surface",
      [](const std::filesystem::path& path) {
        std::shared_ptr<const SurfaceMesh> mesh;
        {
          py::gil_scoped_release release;
          mesh = std::make_shared<const SurfaceMesh>(is_msms_path(path) ? read_msms(path)
                                                                        : read_surface_mesh(path));
        }
        return make_surface(mesh);
      },
      py::arg("path"),
      "Reads .off, .ply (ascii/binary), .obj, .stl (ascii/binary) or an MSMS .vert/.face "
      "pair. Raises InputError (with .file and .line) for missing or malformed files.");
  m.def(
      "read_volume",
      [](const std::filesystem::path& path) {
        std::shared_ptr<const Grid> grid;
        {
          py::gil_scoped_release release;
          grid = std::make_shared<const Grid>(read_volume(path));
        }
        return PyVolume{grid};
      },
      py::arg("path"), "Reads .dx (OpenDX, as APBS writes) or .mrc/.map/.ccp4 volumes.");
  m.def(
      "read_tetmesh",
      [](const std::filesystem::path& path) {
        std::shared_ptr<const TetMesh> mesh;
        {
          py::gil_scoped_release release;
          mesh = std::make_shared<const TetMesh>(read_volume_mesh(path));
        }
        return make_tetmesh(mesh);
      },
      py::arg("path"), "Reads an FETK MCSF file (.m/.mcsf) back into a TetMesh.");
  m.def(
      "read_spheres",
      [](const std::filesystem::path& path) {
        std::vector<Sphere> spheres;
        {
          py::gil_scoped_release release;
          spheres = read_spheres(path);
        }
        return spheres_array(spheres);
      },
      py::arg("path"), "Reads a sphere list (x y z r per line, Å) as an (n, 4) array.");
}

}  // namespace molmesh::python
