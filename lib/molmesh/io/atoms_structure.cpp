#include "molmesh/io/atoms_structure.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <gemmi/cif.hpp>
#include <gemmi/mmcif.hpp>
#include <gemmi/pdb.hpp>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/pdb_records.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

// gemmi's mmCIF errors read "NAME:LINE:COLUMN(BYTE): message" (PEGTL's position);
// returns the line and the message after the position, or nullopt for other messages.
std::optional<std::pair<std::size_t, std::string>> cif_position(std::string_view what) {
  std::size_t i = 0;
  while (i < what.size() && what[i] == ':') ++i;
  std::size_t j = i;
  while (j < what.size() && std::isdigit(static_cast<unsigned char>(what[j]))) ++j;
  if (j == i || j >= what.size() || what[j] != ':') return std::nullopt;
  const auto line = io_detail::parse_integer(what.substr(i, j - i));
  std::size_t k = what.find(": ", j + 1);
  if (!line || k == std::string_view::npos) return std::nullopt;
  return std::pair{static_cast<std::size_t>(*line), std::string(what.substr(k + 2))};
}

// The line of token `target` (0 is the "loop_" keyword, then the tags, then the values) of
// the loop that starts at line `loop_line`, tokenized as gemmi's CIF grammar does: blanks
// are space, tab, CR and LF; '#' at a token start comments to the line end; a value is a
// text field (';' at a line start up to the next line starting with ';'), a quoted string
// (up to the quote followed by a blank or '#') or a run of non-blanks. gemmi keeps no
// position per value, and this runs only to word an error: 0 unless the token found there
// is `value` (so a miscount gives no line rather than a wrong one).
std::size_t cif_token_line(std::string_view text, std::size_t loop_line, std::size_t target,
                           std::string_view value) {
  std::size_t pos = 0, line = 1;
  while (line < loop_line && pos < text.size()) {
    if (text[pos] == '\n') ++line;
    ++pos;
  }
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  std::size_t token = 0;
  while (pos < text.size()) {
    const char c = text[pos];
    if (blank(c)) {
      if (c == '\n') ++line;
      ++pos;
    } else if (c == '#') {
      while (pos < text.size() && text[pos] != '\n') ++pos;
    } else if (token++ == target) {
      const std::size_t end = pos + value.size();
      const bool same = text.substr(pos, value.size()) == value &&
                        (end >= text.size() || blank(text[end]) || text[end] == '#');
      return same ? line : 0;
    } else if (c == ';' && (pos == 0 || text[pos - 1] == '\n')) {
      const std::size_t end = text.find("\n;", pos);
      if (end == std::string_view::npos) return 0;
      line += static_cast<std::size_t>(
          std::count(text.begin() + static_cast<std::ptrdiff_t>(pos),
                     text.begin() + static_cast<std::ptrdiff_t>(end) + 1, '\n'));
      pos = end + 2;
    } else if (c == '\'' || c == '"') {
      ++pos;
      while (pos < text.size() && text[pos] != '\n' &&
             !(text[pos] == c &&
               (pos + 1 == text.size() || blank(text[pos + 1]) || text[pos + 1] == '#')))
        ++pos;
      if (pos < text.size() && text[pos] == c) ++pos;
    } else {
      while (pos < text.size() && !blank(text[pos])) ++pos;
    }
  }
  return 0;
}

// gemmi reads a coordinate it cannot parse ("4.681.0", "0.62w", "?", ".") as NaN and keeps
// the atom, so the block make_structure reads is checked first, with gemmi's own number
// parser so that what passes here is what it reads.
void require_finite_coordinates(gemmi::cif::Block& block, std::string_view text,
                                const std::string& name) {
  gemmi::cif::Table table = block.find("_atom_site.", {"Cartn_x", "Cartn_y", "Cartn_z"});
  const char* axes[3] = {"Cartn_x", "Cartn_y", "Cartn_z"};
  for (const auto row : table) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::string& value = row[k];
      if (std::isfinite(gemmi::cif::as_number(value))) continue;
      const int column = table.positions[k];
      std::size_t line = 0;
      if (table.loop_item != nullptr) {
        const auto& loop = table.loop_item->loop;
        const std::size_t index = static_cast<std::size_t>(row.row_index) * loop.tags.size() +
                                  static_cast<std::size_t>(column);
        const int loop_line = table.loop_item->line_number;
        if (loop_line > 0)
          line = cif_token_line(text, static_cast<std::size_t>(loop_line),
                                1 + loop.tags.size() + index, value);
      } else if (column >= 0) {  // single-atom file: tag-value pairs, the tag's line
        line = static_cast<std::size_t>(
            std::max(0, block.items[static_cast<std::size_t>(column)].line_number));
      }
      throw InputError(name, line,
                       std::string("_atom_site.") + axes[k] + " " + io_detail::quoted(value) +
                           " of atom " + std::to_string(row.row_index + 1) +
                           " is not a finite number");
    }
  }
}

}  // namespace

StructureAtoms parse_structure(const std::string& contents, const std::string& name, bool mmcif,
                               const Reporter& reporter) {
  // gemmi stops a record at a NUL byte and silently drops the next one.
  io_detail::require_no_nul(contents, name);
  if (io_detail::trim(contents).empty())
    throw InputError(name,
                     std::string("empty file: no ") + (mmcif ? "mmCIF data" : "ATOM records"));
  io_detail::PdbScan scan;
  if (!mmcif) {
    scan = io_detail::scan_pdb_records(contents, name);
    if (scan.whitespace_records > 0)
      reporter.warn(name + ": " + std::to_string(scan.whitespace_records) +
                    " ATOM/HETATM records are not in the fixed PDB columns (tabs or shifted "
                    "fields, first at line " +
                    std::to_string(scan.first_whitespace_line) +
                    "); read from their whitespace-separated fields instead");
  }
  const std::string& text = scan.rewritten ? *scan.rewritten : contents;
  gemmi::Structure st;
  try {
    if (mmcif) {
      gemmi::cif::Document doc = gemmi::cif::read_memory(text.data(), text.size(), name.c_str());
      if (doc.blocks.empty()) throw InputError(name, "no data_ block: not an mmCIF file");
      require_finite_coordinates(doc.blocks.front(), text, name);
      st = gemmi::make_structure(std::move(doc));
    } else {
      st = gemmi::read_pdb_from_memory(text.data(), text.size(), name);
    }
  } catch (const InputError&) {
    throw;
  } catch (const std::out_of_range& e) {
    // make_structure indexes tables a damaged file may lack ("vector::_M_range_check").
    throw InputError(name, std::string("cannot parse as ") + (mmcif ? "mmCIF" : "PDB") +
                               ": required data missing or malformed (" + e.what() + ")");
  } catch (const std::exception& e) {
    // gemmi's messages already say what is wrong (and often where): put it in file:line form.
    std::string_view what = e.what();
    if (what.substr(0, name.size()) == name) what.remove_prefix(name.size());
    const std::string format = mmcif ? "mmCIF" : "PDB";
    if (const auto at = cif_position(what))
      throw InputError(name, at->first, "cannot parse as " + format + ": " + at->second);
    while (!what.empty() && (what.front() == ':' || what.front() == ' ')) what.remove_prefix(1);
    throw InputError(name, "cannot parse as " + format + ": " + std::string(what));
  }
  const auto& lines = scan.lines;
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
