// Surface and Volume objects, and molmesh.surface: atoms (or a volume) -> blurred volume ->
// marching cubes -> processed surface, the CLI's `molmesh surface` pipeline.
#include <pybind11/numpy.h>

#include <nlohmann/json.hpp>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casters.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/msms.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/io/surface_mesh_io.hpp"
#include "molmesh/io/volume_io.hpp"
#include "molmesh/io/vtu.hpp"
#include "molmesh/pipeline/parameters_json.hpp"
#include "molmesh/pipeline/report_json.hpp"
#include "molmesh/surface/surface_stats.hpp"
#include "progress.hpp"
#include "surface_objects.hpp"
#include "tables.hpp"

namespace molmesh::python {
namespace {

SurfaceMesh surface_from_arrays(const py::object& vertices, const py::object& faces,
                                const py::object& vertex_markers, const py::object& face_markers) {
  SurfaceMesh mesh;
  mesh.points = to_points(vertices, "vertices");
  mesh.triangles = to_cells<3>(faces, "faces");
  const int n = static_cast<int>(mesh.points.size());
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) {
      if (v < 0 || v >= n)
        throw py::value_error("faces refers to vertex " + std::to_string(v) + " of " +
                              std::to_string(n));
    }
  }
  if (!vertex_markers.is_none()) mesh.vertex_markers = to_ints(vertex_markers, "vertex_markers");
  if (!face_markers.is_none()) mesh.face_markers = to_ints(face_markers, "face_markers");
  if (!mesh.vertex_markers.empty() && mesh.vertex_markers.size() != mesh.points.size())
    throw py::value_error("vertex_markers must have one value per vertex");
  if (!mesh.face_markers.empty() && mesh.face_markers.size() != mesh.triangles.size())
    throw py::value_error("face_markers must have one value per face");
  return mesh;
}

}  // namespace

py::object surface_stats(const SurfaceMesh& mesh) {
  std::string text;
  {
    py::gil_scoped_release release;
    text = to_json(compute_surface_stats(mesh)).dump();
  }
  return json_to_python(text);
}

void write_surface(const std::filesystem::path& path, const SurfaceMesh& mesh) {
  py::gil_scoped_release release;
  if (is_msms_path(path)) {
    write_msms(path, mesh);
  } else if (path.extension() == ".vtu") {
    write_vtu(path, mesh);
  } else if (is_surface_mesh_path(path)) {
    write_surface_mesh(path, mesh);
  } else {
    throw Error("cannot tell the surface format of '" + path.string() +
                "': use .off, .ply, .obj, .stl, .vtu or .vert/.face (MSMS)");
  }
}

py::object make_surface(std::shared_ptr<const SurfaceMesh> mesh, py::object raw,
                        py::object report) {
  return py::cast(PySurface{std::move(mesh), std::move(raw), std::move(report)});
}

void bind_surface(py::module_& m) {
  py::class_<PySurface>(m, "Surface",
                        "A triangle surface: vertices (n, 3) float64 in Å, faces (m, 3) int32 "
                        "counter-clockwise seen from outside, optional int32 markers "
                        "(docs/formats.md). Arrays are read-only views of the C++ data (no "
                        "copy); Surface(vertices, faces) copies its inputs once.")
      .def(py::init([](const py::object& vertices, const py::object& faces,
                       const py::object& vertex_markers, const py::object& face_markers) {
             return PySurface{std::make_shared<const SurfaceMesh>(
                 surface_from_arrays(vertices, faces, vertex_markers, face_markers))};
           }),
           py::arg("vertices"), py::arg("faces"), py::arg("vertex_markers") = py::none(),
           py::arg("face_markers") = py::none())
      .def_property_readonly(
          "vertices",
          [](py::object self) { return points_view(self.cast<PySurface&>().mesh->points, self); },
          "(n, 3) float64 vertex positions, Å (read-only view)")
      .def_property_readonly(
          "faces",
          [](py::object self) { return cells_view(self.cast<PySurface&>().mesh->triangles, self); },
          "(m, 3) int32 vertex indices per triangle (read-only view)")
      .def_property_readonly(
          "vertex_markers",
          [](py::object self) {
            return vector_view(self.cast<PySurface&>().mesh->vertex_markers, self);
          },
          "(n,) int32 vertex markers, or empty")
      .def_property_readonly(
          "face_markers",
          [](py::object self) {
            return vector_view(self.cast<PySurface&>().mesh->face_markers, self);
          },
          "(m,) int32 face markers, or empty")
      .def_readonly("raw", &PySurface::raw,
                    "surface(): the marching-cubes surface before processing; improve(): the "
                    "repaired input; None otherwise")
      .def_readonly("report", &PySurface::report,
                    "dict of what the stage that made this surface measured (stages with "
                    "seconds and stats, ...), None for surfaces built or read")
      .def(
          "stats", [](const PySurface& s) { return surface_stats(*s.mesh); },
          "Quality and topology metrics as a dict with the keys of `molmesh surface "
          "--stats` (vertices, triangles, min_angle_deg, angle_histogram_percent, area Å^2, "
          "volume Å^3, closed, manifold, ...)")
      .def(
          "write",
          [](const PySurface& s, const std::filesystem::path& path) {
            write_surface(path, *s.mesh);
          },
          py::arg("path"),
          "Writes .off, .ply (binary, with markers), .obj, .stl, .vtu or an MSMS .vert/.face "
          "pair, atomically. Raises OutputError when it cannot be written.")
      .def("__repr__", [](const PySurface& s) {
        return "<molmesh.Surface: " + std::to_string(s.mesh->points.size()) + " vertices, " +
               std::to_string(s.mesh->triangles.size()) + " faces>";
      });

  py::class_<PyVolume>(m, "Volume",
                       "A scalar field on a regular grid: values (nx, ny, nz) float64 (x "
                       "fastest in memory, a Fortran-ordered read-only view), origin and "
                       "spacing in Å. values[i, j, k] sits at origin + (i, j, k) * spacing.")
      .def(py::init(
               [](const py::object& values, const py::object& origin, const py::object& spacing) {
                 const auto a =
                     py::array_t<double, py::array::f_style | py::array::forcecast>::ensure(values);
                 if (!a || a.ndim() != 3) throw py::value_error("values must be a 3-d float array");
                 auto grid = std::make_shared<Grid>();
                 for (int k = 0; k < 3; ++k)
                   grid->dims[static_cast<std::size_t>(k)] = static_cast<int>(a.shape(k));
                 grid->values.assign(a.data(), a.data() + a.size());
                 const auto o = to_doubles(origin, "origin");
                 if (o.size() != 3) throw py::value_error("origin must have 3 values");
                 grid->origin = Vec3(o[0], o[1], o[2]);
                 if (py::isinstance<py::float_>(spacing) || py::isinstance<py::int_>(spacing)) {
                   grid->spacing = Vec3::Constant(py::cast<double>(spacing));
                 } else {
                   const auto h = to_doubles(spacing, "spacing");
                   if (h.size() != 3) throw py::value_error("spacing must be a number or 3 values");
                   grid->spacing = Vec3(h[0], h[1], h[2]);
                 }
                 if (!(grid->spacing.minCoeff() > 0.0))
                   throw py::value_error("spacing must be positive");
                 return PyVolume{std::move(grid)};
               }),
           py::arg("values"), py::arg("origin") = py::make_tuple(0.0, 0.0, 0.0),
           py::arg("spacing") = 1.0)
      .def_property_readonly(
          "values",
          [](py::object self) {
            const Grid& g = *self.cast<PyVolume&>().grid;
            const auto d = sizeof(double);
            return read_only(py::array_t<double>(
                {g.dims[0], g.dims[1], g.dims[2]},
                {static_cast<py::ssize_t>(d), static_cast<py::ssize_t>(d) * g.dims[0],
                 static_cast<py::ssize_t>(d) * g.dims[0] * g.dims[1]},
                g.values.data(), self));
          })
      .def_property_readonly("origin",
                             [](const PyVolume& v) {
                               return py::make_tuple(v.grid->origin.x(), v.grid->origin.y(),
                                                     v.grid->origin.z());
                             })
      .def_property_readonly("spacing",
                             [](const PyVolume& v) {
                               return py::make_tuple(v.grid->spacing.x(), v.grid->spacing.y(),
                                                     v.grid->spacing.z());
                             })
      .def_property_readonly("shape",
                             [](const PyVolume& v) {
                               return py::make_tuple(v.grid->dims[0], v.grid->dims[1],
                                                     v.grid->dims[2]);
                             })
      .def(
          "write",
          [](const PyVolume& v, const std::filesystem::path& path) {
            py::gil_scoped_release release;
            write_volume(path, *v.grid);
          },
          py::arg("path"), "Writes .dx (OpenDX as APBS) or .mrc/.map, atomically.")
      .def("__repr__", [](const PyVolume& v) {
        return "<molmesh.Volume: " + std::to_string(v.grid->dims[0]) + " x " +
               std::to_string(v.grid->dims[1]) + " x " + std::to_string(v.grid->dims[2]) + ">";
      });

  const std::string doc =
      "surface(input, *, progress=None, **options) -> Surface\n\n"
      "The `molmesh surface` pipeline: input Atoms are blurred into a volume (GAMer Eq. 1), "
      "a Volume is contoured directly; marching cubes, optional cavity removal, then quality "
      "improvement, coarsening and smoothing unless raw=True. The result's .raw is the "
      "marching-cubes surface and .report has per-stage seconds and stats, grid_dims, "
      "dislocation_max/mean (Å), parameters. progress: callable(stage, fraction). "
      "Options (default):\n" +
      surface_table().describe(SurfacePipelineOptions{});
  m.def(
      "surface",
      [](const py::object& input, py::kwargs kwargs) {
        py::dict kw(kwargs);
        py::object progress = kw.contains("progress") ? kw.attr("pop")("progress") : py::none();
        SurfacePipelineOptions options;
        surface_table().take(kw, options);
        reject_unknown(kw, "surface", names_of(surface_table()));
        const bool atoms_input = py::isinstance<PyAtoms>(input);
        if (!atoms_input && !py::isinstance<PyVolume>(input))
          throw py::type_error("surface() takes molmesh.Atoms or molmesh.Volume");
        std::shared_ptr<const Atoms> atoms = atoms_input ? input.cast<PyAtoms&>().atoms : nullptr;
        std::shared_ptr<const Grid> grid = atoms_input ? nullptr : input.cast<PyVolume&>().grid;
        validate_surface_keywords(options,
                                  atoms_input ? SurfaceInput::kAtoms : SurfaceInput::kVolume);
        PythonProgress bridge(progress);
        auto result = bridge.run([&](const Reporter& r) {
          return std::make_shared<SurfacePipelineResult>(
              atoms ? surface_from_atoms(*atoms, options, r)
                    : surface_from_grid(*grid, options, r));
        });
        nlohmann::json report = surface_result_json(*result);
        report["grid_dims"] = atoms ? result->grid_dims : grid->dims;
        // The CLI's --stats parameters (one writer); the read options of atoms from a file.
        report["parameters"] =
            surface_parameters_json(atoms_input ? surface_source(input.cast<PyAtoms&>(), options)
                                                : SurfaceSource{std::nullopt, options, true});
        py::dict py_report = json_to_python(report.dump());
        py_report["volume"] = py::none();
        if (options.keep_volume && atoms) {
          py_report["volume"] = PyVolume{std::shared_ptr<const Grid>(result, &result->volume)};
        }
        std::shared_ptr<const SurfacePipelineResult> shared = result;
        py::object raw = make_surface(std::shared_ptr<const SurfaceMesh>(shared, &shared->raw),
                                      py::none(), py::none());
        return make_surface(std::shared_ptr<const SurfaceMesh>(shared, &shared->surface), raw,
                            py_report);
      },
      py::arg("input"), doc.c_str());
  register_defaults("surface", [] { return surface_table().values(SurfacePipelineOptions{}); });
}

}  // namespace molmesh::python
