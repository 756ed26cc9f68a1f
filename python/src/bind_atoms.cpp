// Atoms: read from molecule files with the CLI's selection options, or built from arrays
// (an MD frame from MDAnalysis/mdtraj goes in without a file).
#include <pybind11/numpy.h>

#include <cmath>
#include <limits>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "casters.hpp"
#include "errors.hpp"
#include "molmesh/atoms/atom_option_specs.hpp"
#include "molmesh/io/read_atoms.hpp"
#include "molmesh/io/sha256.hpp"
#include "options.hpp"
#include "progress.hpp"
#include "types.hpp"

namespace molmesh::python {
namespace {

const OptionTable<AtomReadOptions>& atom_read_table() {
  static const auto table = [] {
    OptionTable<AtomReadOptions> t;
    const AtomOptionSpecs& specs = kAtomOptionSpecs;
    t.custom(
        std::string(specs.radii.name),
        [](AtomReadOptions& o, py::handle v) {
          if (v.is_none())
            o.radii_file.reset();
          else
            o.radii_file = py::cast<std::filesystem::path>(v);
        },
        [](const AtomReadOptions& o) -> py::object {
          if (!o.radii_file) return py::none();
          return py::str(o.radii_file->string());
        },
        with_keywords(specs.radii.help));
    t.field(std::string(specs.hetatm.name), MOLMESH_FIELD(include_hetatm),
            with_keywords(specs.hetatm.help));
    t.field(std::string(specs.waters.name), MOLMESH_FIELD(include_waters),
            with_keywords(specs.waters.help));
    t.field("hydrogens", MOLMESH_FIELD(include_hydrogens), "include hydrogen atoms");
    return t;
  }();
  return table;
}

template <class Get>
py::array_t<double> column(const Atoms& atoms, Get get) {
  py::array_t<double> out(static_cast<py::ssize_t>(atoms.size()));
  double* p = out.mutable_data();
  for (const Atom& a : atoms) *p++ = get(a);
  return out;
}

template <class Get>
py::list strings(const Atoms& atoms, Get get) {
  py::list out(atoms.size());
  for (std::size_t i = 0; i < atoms.size(); ++i) out[i] = py::str(get(atoms[i]));
  return out;
}

std::shared_ptr<const Atoms> atoms_from_arrays(const py::object& positions, const py::object& radii,
                                               const py::object& charges,
                                               const py::object& blobbyness) {
  const std::vector<Vec3> centers = to_points(positions, "positions");
  const std::vector<double> r = to_doubles(radii, "radii");
  if (r.size() != centers.size())
    throw py::value_error("radii has " + std::to_string(r.size()) + " values for " +
                          std::to_string(centers.size()) + " positions");
  std::vector<double> q, b;
  if (!charges.is_none()) q = to_doubles(charges, "charges");
  if (!blobbyness.is_none()) b = to_doubles(blobbyness, "blobbyness");
  if (!charges.is_none() && q.size() != centers.size())
    throw py::value_error("charges must have one value per position");
  if (!blobbyness.is_none() && b.size() != centers.size())
    throw py::value_error("blobbyness must have one value per position");
  auto atoms = std::make_shared<Atoms>(centers.size());
  for (std::size_t i = 0; i < centers.size(); ++i) {
    Atom& a = (*atoms)[i];
    if (!centers[i].allFinite())
      throw py::value_error("positions[" + std::to_string(i) + "] is not finite");
    if (!(r[i] >= 0.0) || !std::isfinite(r[i]))
      throw py::value_error("radii[" + std::to_string(i) + "] must be finite and >= 0");
    a.center = centers[i];
    a.radius = r[i];
    if (!q.empty()) a.charge = q[i];
    // NaN means "use the global blobbyness", as an unset per-atom value does in files.
    if (!b.empty() && !std::isnan(b[i])) a.blobbyness = b[i];
  }
  return atoms;
}

}  // namespace

void bind_atoms(py::module_& m) {
  py::class_<PyAtoms>(m, "Atoms",
                      "Atom centres (Å), radii (Å), charges (e) and identity fields. Build "
                      "from arrays with Atoms(positions, radii, charges=None, blobbyness=None) "
                      "or read with molmesh.read_atoms(path). Arrays are copies (float64).")
      .def(py::init([](const py::object& positions, const py::object& radii,
                       const py::object& charges, const py::object& blobbyness) {
             return PyAtoms{atoms_from_arrays(positions, radii, charges, blobbyness), std::nullopt};
           }),
           py::arg("positions"), py::arg("radii"), py::arg("charges") = py::none(),
           py::arg("blobbyness") = py::none(),
           "positions: (n, 3) Å; radii: (n,) Å (>= 0; 0 adds nothing to the volume); "
           "charges: (n,) e (default 0); blobbyness: (n,) per-atom B < 0 of Eq. 1, NaN = use "
           "the global value (default all NaN).")
      .def("__len__", [](const PyAtoms& a) { return a.atoms->size(); })
      .def_property_readonly(
          "positions",
          [](const PyAtoms& a) {
            py::array_t<double> out({static_cast<py::ssize_t>(a.atoms->size()), py::ssize_t{3}});
            double* p = out.mutable_data();
            for (const Atom& atom : *a.atoms)
              for (int k = 0; k < 3; ++k) *p++ = atom.center[k];
            return out;
          },
          "(n, 3) float64 atom centres, Å (a copy)")
      .def_property_readonly(
          "radii",
          [](const PyAtoms& a) { return column(*a.atoms, [](const Atom& x) { return x.radius; }); },
          "(n,) float64 radii, Å")
      .def_property_readonly(
          "charges",
          [](const PyAtoms& a) { return column(*a.atoms, [](const Atom& x) { return x.charge; }); },
          "(n,) float64 charges, e")
      .def_property_readonly(
          "blobbyness",
          [](const PyAtoms& a) {
            return column(*a.atoms, [](const Atom& x) {
              return x.blobbyness.value_or(std::numeric_limits<double>::quiet_NaN());
            });
          },
          "(n,) float64 per-atom blobbyness, NaN where the global one applies")
      .def_property_readonly("atom_names",
                             [](const PyAtoms& a) {
                               return strings(*a.atoms, [](const Atom& x) { return x.atom_name; });
                             })
      .def_property_readonly("residue_names",
                             [](const PyAtoms& a) {
                               return strings(*a.atoms,
                                              [](const Atom& x) { return x.residue_name; });
                             })
      .def_property_readonly("residue_numbers",
                             [](const PyAtoms& a) {
                               py::array_t<int> out(static_cast<py::ssize_t>(a.atoms->size()));
                               int* p = out.mutable_data();
                               for (const Atom& x : *a.atoms) *p++ = x.residue_number;
                               return out;
                             })
      .def_property_readonly(
          "chains",
          [](const PyAtoms& a) { return strings(*a.atoms, [](const Atom& x) { return x.chain; }); })
      .def_property_readonly("elements",
                             [](const PyAtoms& a) {
                               return strings(*a.atoms, [](const Atom& x) { return x.element; });
                             })
      .def_property_readonly("hetatm",
                             [](const PyAtoms& a) {
                               py::array_t<bool> out(static_cast<py::ssize_t>(a.atoms->size()));
                               bool* p = out.mutable_data();
                               for (const Atom& x : *a.atoms) *p++ = x.hetatm;
                               return out;
                             })
      .def("__repr__", [](const PyAtoms& a) {
        return "<molmesh.Atoms: " + std::to_string(a.atoms->size()) + " atoms>";
      });

  const std::string doc =
      "read_atoms(path, *, progress=None, **options) -> Atoms\n\n"
      "Reads .pqr (radii and charges from the file), .pdb/.ent, .cif/.mmcif (radii from the "
      "built-in table), optionally gzipped. Raises InputError (with .file and .line) for "
      "unreadable or malformed files. Options (default):\n" +
      atom_read_table().describe(AtomReadOptions{});
  m.def(
      "read_atoms",
      [](const std::filesystem::path& path, py::kwargs kwargs) {
        py::dict kw(kwargs);
        py::object progress = kw.contains("progress") ? kw.attr("pop")("progress") : py::none();
        AtomReadOptions options;
        atom_read_table().take(kw, options);
        reject_unknown(kw, "read_atoms", names_of(atom_read_table()));
        PythonProgress bridge(progress);
        PyAtoms out;
        out.atoms = bridge.run([&](const Reporter& r) {
          return std::make_shared<const Atoms>(read_atoms(path, options, r));
        });
        {
          py::gil_scoped_release release;
          out.source = AtomsSource{path.filename().string(), sha256_file(path), options};
        }
        return out;
      },
      py::arg("path"), doc.c_str());
  register_defaults("read_atoms", [] { return atom_read_table().values(AtomReadOptions{}); });
}

}  // namespace molmesh::python
