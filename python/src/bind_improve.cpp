// molmesh.improve: a user's surface mesh -> repair -> quality improvement, coarsening and
// smoothing, the CLI's `molmesh improve` (lib/molmesh/pipeline/improve_pipeline.hpp).
#include <nlohmann/json.hpp>
#include <string>

#include "bindings.hpp"
#include "casters.hpp"
#include "molmesh/io/stats_json.hpp"
#include "molmesh/pipeline/parameters_json.hpp"
#include "progress.hpp"
#include "surface_objects.hpp"
#include "tables.hpp"

namespace molmesh::python {

void bind_improve(py::module_& m) {
  const std::string doc =
      "improve(vertices_or_surface, faces=None, *, progress=None, **options) -> Surface\n\n"
      "The `molmesh improve` pipeline for meshes from elsewhere (MSMS, EDTSurf, ...): "
      "merge duplicate vertices, drop degenerate and duplicate triangles, orient outward, "
      "then quality improvement, coarsening and smoothing. Takes a Surface, or vertices "
      "(n, 3) and faces (m, 3). The result's .raw is the repaired input; .report has the "
      "repairs and per-stage seconds and stats. Raises Error for meshes with holes or "
      "non-manifold edges. Options (default):\n" +
      improve_table().describe(ImprovePipelineOptions{});
  m.def(
      "improve",
      [](const py::object& input, const py::object& faces, py::kwargs kwargs) {
        py::dict kw(kwargs);
        py::object progress = kw.contains("progress") ? kw.attr("pop")("progress") : py::none();
        ImprovePipelineOptions options;
        improve_table().take(kw, options);
        reject_unknown(kw, "improve", names_of(improve_table()));
        py::object surface = input;
        if (!py::isinstance<PySurface>(input)) {
          if (faces.is_none())
            throw py::type_error("improve() takes a Surface, or vertices and faces");
          surface = py::module_::import("molmesh._core").attr("Surface")(input, faces);
        } else if (!faces.is_none()) {
          throw py::type_error("improve(surface) takes no faces");
        }
        const std::shared_ptr<const SurfaceMesh> mesh = surface.cast<PySurface&>().mesh;
        PythonProgress bridge(progress);
        std::shared_ptr<const ImprovePipelineResult> result = bridge.run([&](const Reporter& r) {
          return std::make_shared<const ImprovePipelineResult>(
              improve_surface(*mesh, "mesh", options, r));
        });
        nlohmann::json report;
        report["repair"] = to_json(result->repair);
        report["repair_seconds"] = result->repair_seconds;
        report["stages"] = to_json(result->stages);
        report["parameters"] = improve_parameters_json(options);  // the CLI's --stats writer
        py::dict py_report = json_to_python(report.dump());
        py::object repaired =
            make_surface(std::shared_ptr<const SurfaceMesh>(result, &result->repaired));
        return make_surface(std::shared_ptr<const SurfaceMesh>(result, &result->surface), repaired,
                            py_report);
      },
      py::arg("vertices_or_surface"), py::arg("faces") = py::none(), doc.c_str());
  register_defaults("improve", [] { return improve_table().values(ImprovePipelineOptions{}); });
}

}  // namespace molmesh::python
