#include "molmesh/io/atoms_structure.hpp"

#include <cctype>
#include <cmath>
#include <gemmi/cif.hpp>
#include <gemmi/mmcif.hpp>
#include <gemmi/pdb.hpp>
#include <set>
#include <unordered_map>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

// Serial number -> line, so that later problems (an element without a radius) can point
// at the record. The first record with a serial wins; gemmi keeps records in file order.
// Also checks the coordinate columns strictly: gemmi reads "-7.1x8" as -7.1 without a word.
std::unordered_map<int, std::size_t> scan_pdb_records(const std::string& contents,
                                                      const std::string& name) {
  std::unordered_map<int, std::size_t> lines;
  io_detail::LineCursor cursor(contents);
  std::string_view line;
  while (cursor.next(line)) {
    if (line.substr(0, 6) != "ATOM  " && line.substr(0, 6) != "HETATM") continue;
    const std::size_t n = cursor.line_number();
    if (line.size() < 54)
      throw InputError(name, n, "ATOM/HETATM record too short for coordinates (columns 31-54)");
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string_view column = io_detail::trim(line.substr(30 + 8 * k, 8));
      const auto value = io_detail::parse_double(column);
      if (!value)
        throw InputError(name, n,
                         std::string(1, "xyz"[k]) + " coordinate '" + std::string(column) +
                             "' (columns " + std::to_string(31 + 8 * k) + "-" +
                             std::to_string(38 + 8 * k) + ") is not a number");
      if (!std::isfinite(*value)) throw InputError(name, n, "coordinates are not finite numbers");
    }
    const auto serial = io_detail::parse_integer(io_detail::trim(line.substr(6, 5)));
    if (serial) lines.emplace(static_cast<int>(*serial), n);
  }
  return lines;
}

}  // namespace

StructureAtoms parse_structure(const std::string& contents, const std::string& name, bool mmcif,
                               const Reporter& reporter) {
  const auto lines =
      mmcif ? std::unordered_map<int, std::size_t>{} : scan_pdb_records(contents, name);
  gemmi::Structure st;
  try {
    if (mmcif) {
      st = gemmi::make_structure(
          gemmi::cif::read_memory(contents.data(), contents.size(), name.c_str()));
    } else {
      st = gemmi::read_pdb_from_memory(contents.data(), contents.size(), name);
    }
  } catch (const std::exception& e) {
    // gemmi's messages already say what is wrong (and often where).
    std::string what = e.what();
    if (what.rfind(name, 0) == 0) what = what.substr(name.size());
    while (!what.empty() && (what.front() == ':' || what.front() == ' ')) what.erase(0, 1);
    throw InputError(name, "cannot parse as " + std::string(mmcif ? "mmCIF" : "PDB") + ": " + what);
  }
  StructureAtoms out;
  if (st.models.empty()) return out;
  if (st.models.size() > 1)
    reporter.warn(name + ": only the first of " + std::to_string(st.models.size()) +
                  " models is used");
  gemmi::Model& model = st.models.front();

  // Of each atom with alternative locations keep the first one listed. (gemmi's
  // remove_alternative_conformations also drops atoms that merely share a name, which
  // small-molecule files do: every carbon of an alkane may be called "C".)
  std::size_t alternative = 0, dropped = 0;
  for (auto& chain : model.chains) {
    for (auto& residue : chain.residues) {
      std::set<std::string> seen;
      std::vector<gemmi::Atom> kept;
      kept.reserve(residue.atoms.size());
      for (auto& atom : residue.atoms) {
        if (atom.altloc != '\0') {
          ++alternative;
          if (!seen.insert(atom.name).second) {
            ++dropped;
            continue;
          }
        }
        kept.push_back(std::move(atom));
      }
      residue.atoms = std::move(kept);
    }
  }
  if (dropped > 0)
    reporter.warn(name + ": " + std::to_string(dropped) + " of " + std::to_string(alternative) +
                  " alternative-location atoms dropped (the first conformer is kept)");

  for (const auto& chain : model.chains) {
    for (const auto& residue : chain.residues) {
      for (const auto& a : residue.atoms) {
        Atom atom;
        atom.center = Vec3(a.pos.x, a.pos.y, a.pos.z);
        atom.charge = static_cast<double>(a.charge);  // formal charge, if the file has one
        atom.atom_name = a.name;
        atom.residue_name = residue.name;
        atom.residue_number = residue.seqid.num.has_value() ? residue.seqid.num.value : 0;
        atom.chain = chain.name;
        atom.hetatm = residue.het_flag == 'H';
        if (a.element != gemmi::El::X) atom.element = a.element.uname();
        out.atoms.push_back(std::move(atom));
        const auto it = lines.find(a.serial);
        out.lines.push_back(it == lines.end() ? 0 : it->second);
      }
    }
  }
  return out;
}

}  // namespace molmesh
