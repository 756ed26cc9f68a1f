// TetMesh objects and molmesh.tetmesh: a surface (or atoms, through the surface pipeline)
// -> TetGen tetrahedral mesh of the molecule, the solvent or both, as `molmesh tetmesh`.
#include <pybind11/numpy.h>

#include <nlohmann/json.hpp>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casters.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/io/volume_mesh_io.hpp"
#include "molmesh/pipeline/parameters_json.hpp"
#include "molmesh/tetmesh/tet_stats.hpp"
#include "progress.hpp"
#include "surface_objects.hpp"
#include "tables.hpp"
#include "tetmesh_objects.hpp"

namespace molmesh::python {
namespace {

std::vector<PointField> point_fields(const py::object& fields, std::size_t points) {
  std::vector<PointField> out;
  if (fields.is_none()) return out;
  for (const auto& item : py::cast<py::dict>(fields)) {
    PointField f{py::cast<std::string>(item.first),
                 to_doubles(py::reinterpret_borrow<py::object>(item.second), "point field")};
    if (f.values.size() != points)
      throw py::value_error("point field '" + f.name + "' has " + std::to_string(f.values.size()) +
                            " values for " + std::to_string(points) + " vertices");
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace

py::object make_tetmesh(std::shared_ptr<const TetMesh> mesh, py::object report) {
  return py::cast(PyTetMesh{std::move(mesh), std::move(report)});
}

void bind_tetmesh(py::module_& m) {
  py::class_<PyTetMesh>(m, "TetMesh",
                        "A tetrahedral mesh: vertices (n, 3) float64 Å, tetrahedra (k, 4) int32 "
                        "positively oriented, cell_markers (k,) region (1 molecule, 2 solvent), "
                        "vertex_markers (n,), boundary_faces (f, 3) int32 oriented outward and "
                        "boundary_face_markers (f,) (1 molecular surface, 2 outer sphere, 3 "
                        "active site; docs/formats.md). Read-only views, no copy.")
      .def_property_readonly(
          "vertices",
          [](py::object self) { return points_view(self.cast<PyTetMesh&>().mesh->points, self); })
      .def_property_readonly("tetrahedra",
                             [](py::object self) {
                               return cells_view(self.cast<PyTetMesh&>().mesh->tetrahedra, self);
                             })
      .def_property_readonly("cell_markers",
                             [](py::object self) {
                               return vector_view(self.cast<PyTetMesh&>().mesh->cell_markers, self);
                             })
      .def_property_readonly("vertex_markers",
                             [](py::object self) {
                               return vector_view(self.cast<PyTetMesh&>().mesh->vertex_markers,
                                                  self);
                             })
      .def_property_readonly("boundary_faces",
                             [](py::object self) {
                               return cells_view(self.cast<PyTetMesh&>().mesh->boundary_faces,
                                                 self);
                             })
      .def_property_readonly("boundary_face_markers",
                             [](py::object self) {
                               return vector_view(
                                   self.cast<PyTetMesh&>().mesh->boundary_face_markers, self);
                             })
      .def_readonly("report", &PyTetMesh::report,
                    "tetmesh(): dict with 'tetgen' (switches, seconds, atoms as nodes, outer "
                    "radius, ...), 'surface' (the meshed molecular Surface), 'parameters'")
      .def(
          "stats",
          [](const PyTetMesh& t) {
            std::string text;
            {
              py::gil_scoped_release release;
              text = to_json(compute_tet_stats(*t.mesh)).dump();
            }
            return json_to_python(text);
          },
          "Quality numbers with the keys of `molmesh tetmesh --stats` (counts per region and "
          "marker, dihedral angles in degrees, radius-edge ratios, volumes in Å^3)")
      .def(
          "write",
          [](const PyTetMesh& t, const std::filesystem::path& path, const py::object& fields) {
            const auto f = point_fields(fields, t.mesh->points.size());
            py::gil_scoped_release release;
            write_volume_mesh(path, *t.mesh, f);
          },
          py::arg("path"), py::arg("point_fields") = py::none(),
          "Writes .m/.mcsf (FETK MCSF), .vtu (with optional point_fields {name: (n,) "
          "array}), .msh (Gmsh 2.2) or .msh4, atomically.")
      .def("__repr__", [](const PyTetMesh& t) {
        return "<molmesh.TetMesh: " + std::to_string(t.mesh->points.size()) + " vertices, " +
               std::to_string(t.mesh->tetrahedra.size()) + " tetrahedra>";
      });

  const std::string doc =
      "tetmesh(input, atoms=None, *, progress=None, **options) -> TetMesh\n\n"
      "The `molmesh tetmesh` stage (TetGen, GAMer §2.4). input: a closed Surface (meshed as "
      "given; pass the Atoms too so their centres become nodes of the interior), or Atoms "
      "(the surface pipeline runs first and takes the surface() options as well). Tetmesh "
      "options (default):\n" +
      tetmesh_table().describe(TetMeshOptions{});
  m.def(
      "tetmesh",
      [](const py::object& input, const py::object& atoms_arg, py::kwargs kwargs) {
        py::dict kw(kwargs);
        py::object progress = kw.contains("progress") ? kw.attr("pop")("progress") : py::none();
        TetMeshOptions options;
        tetmesh_table().take(kw, options);
        const bool atoms_input = py::isinstance<PyAtoms>(input);
        SurfacePipelineOptions surface_options;
        if (atoms_input) {
          surface_table().take(kw, surface_options);
          reject_unknown(kw, "tetmesh", names_of(tetmesh_table(), surface_table()));
        } else {
          reject_unknown(kw, "tetmesh", names_of(tetmesh_table()));
        }
        if (!atoms_input && !py::isinstance<PySurface>(input))
          throw py::type_error("tetmesh() takes a molmesh.Surface or molmesh.Atoms");
        std::shared_ptr<const Atoms> atoms;
        if (atoms_input) {
          atoms = input.cast<PyAtoms&>().atoms;
        } else if (!atoms_arg.is_none()) {
          atoms = atoms_arg.cast<PyAtoms&>().atoms;
        }
        std::shared_ptr<const SurfaceMesh> surface =
            atoms_input ? nullptr : input.cast<PySurface&>().mesh;
        if (atoms_input) validate_surface_keywords(surface_options, SurfaceInput::kAtoms);
        static const Atoms kNoAtoms;
        PythonProgress bridge(progress);
        struct Out {
          std::shared_ptr<const SurfaceMesh> surface;
          std::shared_ptr<const TetMesh> mesh;
          TetMeshReport report;
        };
        Out out = bridge.run([&](const Reporter& r) {
          Out o;
          o.surface = surface;
          if (!o.surface) {
            o.surface = std::make_shared<const SurfaceMesh>(
                std::move(surface_from_atoms(*atoms, surface_options, r).surface));
          }
          o.mesh = std::make_shared<const TetMesh>(
              tetrahedralize(*o.surface, atoms ? *atoms : kNoAtoms, options, r, &o.report));
          return o;
        });
        // The CLI's --stats tetgen object and parameters (one writer each).
        std::optional<SurfaceSource> source;
        if (atoms_input) source = surface_source(input.cast<PyAtoms&>(), surface_options);
        const nlohmann::json json = {{"tetgen", to_json(out.report)},
                                     {"parameters", tetmesh_parameters_json(options, source)}};
        py::dict report = json_to_python(json.dump());
        report["surface"] = atoms_input ? make_surface(out.surface) : input;
        return make_tetmesh(out.mesh, report);
      },
      py::arg("input"), py::arg("atoms") = py::none(), doc.c_str());
  register_defaults("tetmesh", [] { return tetmesh_table().values(TetMeshOptions{}); });
}

}  // namespace molmesh::python
