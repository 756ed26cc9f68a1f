// Hierarchy objects, molmesh.hierarchy (atoms -> raw surface -> multilevel surface and
// volume meshes with prolongations, as `molmesh hierarchy`) and molmesh.read_hierarchy.
#include <pybind11/numpy.h>

#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casters.hpp"
#include "hierarchy_objects.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/pipeline/hierarchy_parameters.hpp"
#include "molmesh/pipeline/hierarchy_surface.hpp"
#include "molmesh/pipeline/report_json.hpp"
#include "progress.hpp"
#include "surface_objects.hpp"
#include "tables.hpp"
#include "tetmesh_objects.hpp"

namespace molmesh::python {
namespace {

// One level of a hierarchy; its meshes alias into the Hierarchy (no copy).
struct PyLevel {
  std::shared_ptr<const Hierarchy> hierarchy;
  std::size_t index = 0;
  const HierarchyLevel& level() const { return hierarchy->levels[index]; }
};

// scipy.sparse.csr_matrix of a row-major Eigen matrix: one copy of its three arrays.
py::object csr_matrix(const SparseMatrix& matrix) {
  SparseMatrix compressed;
  const SparseMatrix* m = &matrix;
  if (!matrix.isCompressed()) {
    compressed = matrix;
    compressed.makeCompressed();
    m = &compressed;
  }
  const auto nnz = static_cast<py::ssize_t>(m->nonZeros());
  py::array_t<double> data(nnz);
  py::array_t<int> indices(nnz);
  py::array_t<int> indptr(static_cast<py::ssize_t>(m->outerSize()) + 1);
  std::copy_n(m->valuePtr(), nnz, data.mutable_data());
  std::copy_n(m->innerIndexPtr(), nnz, indices.mutable_data());
  std::copy_n(m->outerIndexPtr(), m->outerSize() + 1, indptr.mutable_data());
  py::object scipy_sparse = py::module_::import("scipy.sparse");
  return scipy_sparse.attr("csr_matrix")(py::make_tuple(data, indices, indptr),
                                         py::arg("shape") = py::make_tuple(m->rows(), m->cols()));
}

}  // namespace

py::object make_hierarchy(std::shared_ptr<const Hierarchy> hierarchy, py::object report) {
  return py::cast(PyHierarchy{std::move(hierarchy), std::move(report)});
}

void bind_hierarchy(py::module_& m) {
  py::class_<PyLevel>(m, "HierarchyLevel",
                      "One level of a Hierarchy (0 = finest): t0, surface (Surface), volume "
                      "(TetMesh), surface_provenance and volume_permutation (int32 arrays).")
      .def_property_readonly("t0", [](const PyLevel& l) { return l.level().t0; })
      .def_property_readonly("surface",
                             [](const PyLevel& l) {
                               return make_surface(std::shared_ptr<const SurfaceMesh>(
                                   l.hierarchy, &l.level().surface));
                             })
      .def_property_readonly(
          "volume",
          [](const PyLevel& l) {
            return make_tetmesh(std::shared_ptr<const TetMesh>(l.hierarchy, &l.level().volume));
          })
      .def_property_readonly(
          "surface_provenance",
          [](py::object self) {
            return vector_view(self.cast<PyLevel&>().level().surface_provenance, self);
          },
          "coarse surface vertex -> vertex of the next finer level's surface "
          "(empty on level 0)")
      .def_property_readonly(
          "volume_permutation",
          [](py::object self) {
            return vector_view(self.cast<PyLevel&>().level().volume_permutation, self);
          },
          "new volume vertex index -> index in the mesher's output (empty = "
          "identity)")
      .def("__repr__", [](const PyLevel& l) {
        return "<molmesh.HierarchyLevel " + std::to_string(l.index) + ": T0 " +
               std::to_string(l.level().t0) + ", " +
               std::to_string(l.level().volume.points.size()) + " volume vertices>";
      });

  py::class_<PyHierarchy>(m, "Hierarchy",
                          "Multilevel meshes for multigrid (GAMer §4.3): levels[0] finest; "
                          "prolongations[i] (scipy.sparse.csr_matrix, fine x coarse) maps level "
                          "i+1 volume values to level i (restriction = transpose).")
      .def_property_readonly("levels",
                             [](const PyHierarchy& h) {
                               py::list out;
                               for (std::size_t i = 0; i < h.hierarchy->levels.size(); ++i)
                                 out.append(PyLevel{h.hierarchy, i});
                               return out;
                             })
      .def("__len__", [](const PyHierarchy& h) { return h.hierarchy->levels.size(); })
      .def_property_readonly(
          "prolongations",
          [](const PyHierarchy& h) {
            py::list out;
            for (const LevelTransfer& t : h.hierarchy->transfers) out.append(csr_matrix(t.volume));
            return out;
          },
          "volume prolongations, level i+1 -> i (copies, float64 CSR)")
      .def_property_readonly("surface_prolongations",
                             [](const PyHierarchy& h) {
                               py::list out;
                               for (const LevelTransfer& t : h.hierarchy->transfers)
                                 out.append(csr_matrix(t.surface));
                               return out;
                             })
      .def_property_readonly(
          "parameters", [](const PyHierarchy& h) { return h.hierarchy->parameters; },
          "every meshing parameter as text (as stored in the HDF5 file)")
      .def_property_readonly("input_name",
                             [](const PyHierarchy& h) { return h.hierarchy->input_name; })
      .def_property_readonly("input_checksum",
                             [](const PyHierarchy& h) { return h.hierarchy->input_checksum; })
      .def_readonly("report", &PyHierarchy::report)
      .def(
          "write",
          [](const PyHierarchy& h, const std::filesystem::path& path) {
            py::gil_scoped_release release;
            write_hierarchy(path, *h.hierarchy);
          },
          py::arg("path"),
          "Writes the HDF5 file (docs/formats.md) and its XDMF sidecars, atomically.")
      .def("__repr__", [](const PyHierarchy& h) {
        return "<molmesh.Hierarchy: " + std::to_string(h.hierarchy->levels.size()) + " levels>";
      });

  const std::string doc =
      "hierarchy(input, atoms=None, *, progress=None, **options) -> Hierarchy\n\n"
      "The `molmesh hierarchy` stage: Atoms are blurred and contoured (raw; the volume "
      "options of surface() apply: surface, probe_radius, keep_on_surface, spacing, "
      "blobbyness, isovalue, truncation, blur, min_cavity_volume), "
      "or a Surface is taken as given (pass atoms= for interior nodes); then one level per "
      "T0, each with its own surface processing, volume mesh and prolongation. As in the "
      "CLI, active_site spheres are also kept dense by coarsening on every level. Options "
      "(default):\n" +
      keep_spheres_table().describe(SurfacePipelineOptions{}) +
      hierarchy_table().describe(HierarchyOptions{});
  m.def(
      "hierarchy",
      [](const py::object& input, const py::object& atoms_arg, py::kwargs kwargs) {
        py::dict kw(kwargs);
        py::object progress = kw.contains("progress") ? kw.attr("pop")("progress") : py::none();
        // A sphere file's name is recorded as the CLI records --active-site's.
        std::string active_site_file;
        if (kw.contains("active_site") && is_path(kw["active_site"]))
          active_site_file = py::cast<std::filesystem::path>(kw["active_site"]).string();
        HierarchyOptions options;
        hierarchy_table().take(kw, options);
        const bool atoms_input = py::isinstance<PyAtoms>(input);
        SurfacePipelineOptions surface_options;
        keep_spheres_table().take(kw, surface_options);
        if (atoms_input) {
          volume_table().take(kw, surface_options);
          reject_unknown(kw, "hierarchy",
                         names_of(hierarchy_table(), keep_spheres_table(), volume_table()));
        } else {
          reject_unknown(kw, "hierarchy", names_of(hierarchy_table(), keep_spheres_table()));
        }
        if (!atoms_input && !py::isinstance<PySurface>(input))
          throw py::type_error("hierarchy() takes molmesh.Atoms or a molmesh.Surface");
        std::shared_ptr<const Atoms> atoms;
        if (atoms_input)
          atoms = input.cast<PyAtoms&>().atoms;
        else if (!atoms_arg.is_none())
          atoms = atoms_arg.cast<PyAtoms&>().atoms;
        std::shared_ptr<const SurfaceMesh> surface =
            atoms_input ? nullptr : input.cast<PySurface&>().mesh;
        static const Atoms kNoAtoms;
        PythonProgress bridge(progress);
        struct Out {
          std::shared_ptr<Hierarchy> hierarchy;
          HierarchyReport report;
        };
        Out out = bridge.run([&](const Reporter& r) {
          Out o;
          std::shared_ptr<const SurfaceMesh> s = surface;
          // As `molmesh hierarchy` (one library function for both): the keep spheres and
          // the active site stay dense on every level, vertices stay on the surface.
          if (!s) {
            SurfacePipelineResult result =
                surface_from_atoms(*atoms, hierarchy_surface_options(surface_options), r);
            process_levels_as(options, surface_options, result.projection);
            s = std::make_shared<const SurfaceMesh>(std::move(result.surface));
          } else {
            process_levels_as(options, surface_options, {});
          }
          o.hierarchy = std::make_shared<Hierarchy>(
              build_hierarchy(*s, atoms ? *atoms : kNoAtoms, options, r, &o.report));
          return o;
        });
        // Recorded in the file as `molmesh hierarchy` records them (one writer for both).
        const PyAtoms* read = atoms_input ? &input.cast<PyAtoms&>() : nullptr;
        std::optional<SurfaceSource> source;
        if (read) source = surface_source(*read, surface_options);
        out.hierarchy->parameters =
            hierarchy_parameters(options, out.report, active_site_file, source);
        if (read && read->source) {
          out.hierarchy->input_name = read->source->name;
          out.hierarchy->input_checksum = read->source->checksum;
        }
        // The keys of `molmesh hierarchy --stats`, whose parameters are the file's.
        py::dict report = json_to_python(to_json(out.report).dump());
        report["parameters"] = py::cast(out.hierarchy->parameters);
        return make_hierarchy(std::move(out.hierarchy), report);
      },
      py::arg("input"), py::arg("atoms") = py::none(), doc.c_str());
  register_defaults("hierarchy", [] {
    py::dict d = volume_table().values(SurfacePipelineOptions{});
    d.attr("update")(keep_spheres_table().values(SurfacePipelineOptions{}));
    d.attr("update")(hierarchy_table().values(HierarchyOptions{}));
    return d;
  });

  m.def(
      "read_hierarchy",
      [](const std::filesystem::path& path) {
        std::shared_ptr<const Hierarchy> h;
        {
          py::gil_scoped_release release;
          h = std::make_shared<const Hierarchy>(read_hierarchy(path));
        }
        return make_hierarchy(h);
      },
      py::arg("path"),
      "Loads a hierarchy HDF5 file (from `molmesh hierarchy` or Hierarchy.write). Raises "
      "InputError when it is missing or not a molmesh hierarchy.");
  m.def(
      "write_point_field",
      [](const std::filesystem::path& path, int level, const std::string& name,
         const py::object& values) {
        const std::vector<double> v = to_doubles(values, "values");
        py::gil_scoped_release release;
        write_point_field(path, level, name, v);
      },
      py::arg("path"), py::arg("level"), py::arg("name"), py::arg("values"),
      "Stores one value per volume vertex of `level` in the hierarchy file (ParaView shows it "
      "through the XDMF sidecar).");
  m.def(
      "write_point_fields",
      [](const std::filesystem::path& path, int level, const py::dict& fields) {
        // Copied out of numpy first, so the file is rewritten without the GIL, once.
        std::vector<std::string> names;
        std::vector<std::vector<double>> values;
        for (const auto& [key, value] : fields) {
          names.push_back(py::cast<std::string>(key));
          values.push_back(
              to_doubles(py::reinterpret_borrow<py::object>(value), names.back().c_str()));
        }
        std::vector<PointFieldView> list;
        for (std::size_t i = 0; i < names.size(); ++i) list.push_back({names[i], values[i]});
        py::gil_scoped_release release;
        write_point_fields(path, level, list);
      },
      py::arg("path"), py::arg("level"), py::arg("fields"),
      "Stores several fields {name: values} of `level` with one rewrite of the file: all of "
      "them or, when any has a bad name or length, none.");
  m.def(
      "read_point_field",
      [](const std::filesystem::path& path, int level, const std::string& name) {
        std::vector<double> v;
        {
          py::gil_scoped_release release;
          v = read_point_field(path, level, name);
        }
        py::array_t<double> out(static_cast<py::ssize_t>(v.size()));
        std::copy(v.begin(), v.end(), out.mutable_data());
        return out;
      },
      py::arg("path"), py::arg("level"), py::arg("name"));
  m.def("point_field_names", &point_field_names, py::arg("path"), py::arg("level"));
}

}  // namespace molmesh::python
