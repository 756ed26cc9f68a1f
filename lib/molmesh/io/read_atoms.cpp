#include "molmesh/io/read_atoms.hpp"

#include <array>
#include <cctype>
#include <cmath>

#include "molmesh/atoms/radius_table.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/atoms_pqr.hpp"
#include "molmesh/io/atoms_structure.hpp"
#include "molmesh/io/radius_table.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

// PQR carries no element: a name whose first letter (after digits, as in "1HB") is H is a
// hydrogen, except single-atom residues named like the atom (Hg, Ho ions).
bool is_hydrogen(const Atom& atom) {
  if (!atom.element.empty()) {
    const std::string e = to_upper(atom.element);
    return e == "H" || e == "D";
  }
  std::size_t i = 0;
  while (i < atom.atom_name.size() && std::isdigit(static_cast<unsigned char>(atom.atom_name[i])))
    ++i;
  if (i >= atom.atom_name.size()) return false;
  const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(atom.atom_name[i])));
  if (c != 'H' && c != 'D') return false;
  return to_upper(atom.atom_name) != to_upper(atom.residue_name);
}

std::string describe(const Atom& atom) {
  return "atom " + atom.atom_name + " of " + atom.residue_name + " " +
         std::to_string(atom.residue_number) + (atom.chain.empty() ? "" : " chain " + atom.chain);
}

}  // namespace

bool is_water_residue(std::string_view residue_name) {
  static constexpr std::array<std::string_view, 14> kWaters{"HOH", "WAT",  "H2O",  "DOD",  "D2O",
                                                            "TIP", "TIP3", "TIP4", "TIP5", "T3P",
                                                            "T4P", "SPC",  "SOL",  "HOD"};
  const std::string upper = to_upper(residue_name);
  for (auto w : kWaters)
    if (upper == w) return true;
  return false;
}

Atoms read_atoms(const std::filesystem::path& path, const AtomReadOptions& options,
                 const Reporter& reporter) {
  const std::string name = path.string();
  const std::string ext = io_detail::format_extension(path);
  const bool pqr = ext == ".pqr";
  const bool pdb = ext == ".pdb" || ext == ".ent";
  const bool cif = ext == ".cif" || ext == ".mmcif";
  if (!pqr && !pdb && !cif)
    throw InputError(name, "unknown molecule format '" + ext +
                               "' (expected .pqr, .pdb, .ent, .cif or .mmcif, optionally .gz)");
  // Read the user table first: a broken table should fail before a long parse.
  std::optional<RadiusTable> user_table;
  if (options.radii_file) user_table = read_radius_table(*options.radii_file);

  reporter.progress("read atoms", 0.0);
  const std::string contents = io_detail::read_file_contents(path);
  StructureAtoms read;
  if (pqr) {
    read.atoms = parse_pqr(contents, name, reporter);
  } else {
    read = parse_structure(contents, name, cif, reporter);
  }
  if (read.atoms.empty()) throw InputError(name, "no ATOM or HETATM records: nothing to mesh");

  Atoms atoms;
  std::vector<std::size_t> lines;
  atoms.reserve(read.atoms.size());
  for (std::size_t i = 0; i < read.atoms.size(); ++i) {
    const Atom& atom = read.atoms[i];
    if (!options.include_hetatm && atom.hetatm) continue;
    if (!options.include_waters && is_water_residue(atom.residue_name)) continue;
    if (!options.include_hydrogens && is_hydrogen(atom)) continue;
    atoms.push_back(atom);
    if (i < read.lines.size()) lines.push_back(read.lines[i]);
  }
  if (atoms.empty())
    throw InputError(name, "all " + std::to_string(read.atoms.size()) +
                               " atoms were excluded by the HETATM/water/hydrogen options");

  for (std::size_t i = 0; i < atoms.size(); ++i) {
    Atom& atom = atoms[i];
    if (!pqr && !atom.center.allFinite())
      throw InputError(name, i < lines.size() ? lines[i] : 0,
                       describe(atom) + ": non-finite coordinates");
    std::optional<double> radius;
    if (user_table) radius = user_table->lookup(atom);
    if (!radius && !pqr) {
      radius = builtin_radius_table().lookup(atom);
      if (!radius) {
        const std::string what =
            atom.element.empty()
                ? "has no element symbol (none in the file, and the name does not identify one)"
                : "has element " + atom.element + ", which has no radius in the built-in table";
        throw InputError(name, i < lines.size() ? lines[i] : 0,
                         describe(atom) + " " + what +
                             "; give one in a radius table (`radii_file`; a line '" +
                             (atom.element.empty() ? std::string("*") : to_upper(atom.element)) +
                             " 1.80', see docs/formats.md) or exclude HETATM records");
      }
    }
    if (radius) atom.radius = *radius;
  }

  std::size_t zero = 0;
  for (const Atom& atom : atoms)
    if (atom.radius == 0.0) ++zero;
  if (zero > 0)
    reporter.warn(name + ": " + std::to_string(zero) +
                  " atoms have zero radius and add nothing to the surface");
  reporter.progress("read atoms", 1.0);
  return atoms;
}

}  // namespace molmesh
