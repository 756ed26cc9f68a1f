#include "molmesh/io/atoms_structure.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <gemmi/atox.hpp>
#include <gemmi/cif.hpp>
#include <gemmi/mmcif.hpp>
#include <gemmi/pdb.hpp>
#include <limits>
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

// The line of the value in column k of `row` (0 when unknown): in a loop, found by
// re-tokenizing it (cif_token_line); for tag-value pairs, the tag's line.
std::size_t value_line(gemmi::cif::Block& block, const gemmi::cif::Table& table, int row_index,
                       std::size_t k, std::string_view text, const std::string& value) {
  const int column = table.positions[k];
  if (table.loop_item != nullptr) {
    const auto& loop = table.loop_item->loop;
    const std::size_t index =
        static_cast<std::size_t>(row_index) * loop.tags.size() + static_cast<std::size_t>(column);
    const int loop_line = table.loop_item->line_number;
    if (loop_line <= 0) return 0;
    return cif_token_line(text, static_cast<std::size_t>(loop_line), 1 + loop.tags.size() + index,
                          value);
  }
  if (column < 0) return 0;
  return static_cast<std::size_t>(
      std::max(0, block.items[static_cast<std::size_t>(column)].line_number));
}

// "_atom_site.Cartn_y '4.681.0' of atom 4", the start of a message about one value.
std::string value_label(std::string_view category, std::string_view tag, std::string_view value,
                        int row_index) {
  const bool atoms = category == "_atom_site.";
  // A quoted CIF value is shown without its quotes ("'(1-60)'" as '(1-60)').
  const bool quoted = value.size() >= 2 && (value.front() == '\'' || value.front() == '"');
  if (quoted) value = value.substr(1, value.size() - 2);
  return std::string(category) + std::string(tag) + " " + io_detail::quoted(value) +
         (atoms ? " of atom " : " of row ") + std::to_string(row_index + 1);
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
      throw InputError(
          name, value_line(block, table, row.row_index, k, text, value),
          value_label("_atom_site.", axes[k], value, row.row_index) + " is not a finite number");
    }
  }
}

// How gemmi 0.5's make_structure turns a column into an int (gemmi/mmcif.hpp, atox.hpp).
// Its parsers do not check for overflow (a 40-digit _atom_site.id is signed overflow,
// undefined behaviour) and a value that is not a number throws without a line, so every
// column it reads as an int is checked here first, the way that column is read.
enum class IntRead {
  kWhole,          // cif::as_int: '?' or '.', or the whole value is one integer
  kSequenceId,     // make_seqid: an integer, optionally followed by an insertion-code letter
  kLeadingDigits,  // string_to_int unchecked, no_sign_atoi: leading digits, the rest ignored
  kOperators,      // parse_operation_expr: "1,3-5" or "(1-60)", each range expanded
};
struct IntColumn {
  const char* category;
  const char* tag;
  IntRead read;
};
// Every column make_structure reads as an int: keep in step with gemmi/mmcif.hpp
// (grep as_int, copy_int, make_resid, string_to_int, no_sign_atoi). Columns it reads only
// when all of a table's columns exist are checked whenever present: a value there that is
// not an integer is wrong either way.
constexpr IntColumn kIntColumns[] = {
    {"_atom_site.", "id", IntRead::kLeadingDigits},
    {"_atom_site.", "label_seq_id", IntRead::kWhole},
    {"_atom_site.", "auth_seq_id", IntRead::kSequenceId},
    {"_atom_site.", "pdbx_formal_charge", IntRead::kWhole},
    {"_atom_site.", "pdbx_tls_group_id", IntRead::kLeadingDigits},
    {"_refine.", "ls_number_reflns_obs", IntRead::kWhole},
    {"_exptl.", "crystals_number", IntRead::kWhole},
    {"_reflns.", "number_obs", IntRead::kWhole},
    {"_software.", "pdbx_ordinal", IntRead::kWhole},
    {"_struct_conf.", "beg_auth_seq_id", IntRead::kSequenceId},
    {"_struct_conf.", "end_auth_seq_id", IntRead::kSequenceId},
    {"_struct_conf.", "pdbx_PDB_helix_class", IntRead::kWhole},
    {"_struct_conf.", "pdbx_PDB_helix_length", IntRead::kWhole},
    {"_struct_sheet_range.", "beg_auth_seq_id", IntRead::kSequenceId},
    {"_struct_sheet_range.", "end_auth_seq_id", IntRead::kSequenceId},
    {"_pdbx_struct_sheet_hbond.", "range_1_auth_seq_id", IntRead::kSequenceId},
    {"_pdbx_struct_sheet_hbond.", "range_2_auth_seq_id", IntRead::kSequenceId},
    {"_struct_conn.", "ptnr1_auth_seq_id", IntRead::kSequenceId},
    {"_struct_conn.", "ptnr2_auth_seq_id", IntRead::kSequenceId},
    {"_struct_conn.", "ptnr1_label_seq_id", IntRead::kWhole},
    {"_struct_conn.", "ptnr2_label_seq_id", IntRead::kWhole},
    {"_struct_mon_prot_cis.", "auth_seq_id", IntRead::kSequenceId},
    {"_pdbx_struct_assembly.", "oligomeric_count", IntRead::kWhole},
    {"_pdbx_struct_assembly_gen.", "oper_expression", IntRead::kOperators},
    {"_pdbx_sifts_xref_db.", "seq_id", IntRead::kWhole},
    {"_pdbx_sifts_xref_db.", "unp_num", IntRead::kWhole},
    {"_entity_poly_seq.", "num", IntRead::kWhole},
    {"_struct_ref_seq.", "seq_align_beg", IntRead::kWhole},
    {"_struct_ref_seq.", "seq_align_end", IntRead::kWhole},
    {"_struct_ref_seq.", "db_align_beg", IntRead::kWhole},
    {"_struct_ref_seq.", "db_align_end", IntRead::kWhole},
    {"_struct_ref_seq.", "pdbx_auth_seq_align_beg", IntRead::kSequenceId},
    {"_struct_ref_seq.", "pdbx_auth_seq_align_end", IntRead::kSequenceId},
};

// An assembly's operator list is expanded one operator at a time; real ones list a few
// dozen (60 for an icosahedron); a range of millions is a damaged file, and listing it
// would take gigabytes.
constexpr long long kMaxAssemblyOperators = 1000000;

constexpr long long kIntMin = std::numeric_limits<int>::min();
constexpr long long kIntMax = std::numeric_limits<int>::max();

bool digit(char c) { return c >= '0' && c <= '9'; }

// The optional sign and digits at s[i...] as gemmi's string_to_int reads them (i is moved past
// them); `digits` says whether there were any. nullopt when the number is outside int.
std::optional<long long> leading_integer(std::string_view s, std::size_t& i, bool& digits,
                                         bool sign = true) {
  while (i < s.size() && gemmi::is_space(s[i])) ++i;
  bool negative = false;
  if (sign && i < s.size() && (s[i] == '-' || s[i] == '+')) negative = s[i++] == '-';
  long long n = 0;
  bool overflow = false;
  digits = false;
  for (; i < s.size() && digit(s[i]); ++i) {
    digits = true;
    if (!overflow) n = n * 10 + (s[i] - '0');
    overflow = overflow || n > kIntMax + 1;
  }
  if (overflow || (negative ? -n < kIntMin : n > kIntMax)) return std::nullopt;
  return negative ? -n : n;
}

// Why gemmi cannot read `raw` as `read` says, or empty when it can.
std::string int_problem(const std::string& raw, IntRead read) {
  const std::string range =
      "an integer from " + std::to_string(kIntMin) + " to " + std::to_string(kIntMax);
  const auto whole = [&](std::string_view s) -> std::string {
    std::size_t i = 0;
    bool digits = false;
    const auto n = leading_integer(s, i, digits);
    while (i < s.size() && gemmi::is_space(s[i])) ++i;
    if (!digits || i != s.size()) return "is not an integer";
    return n ? "" : "is not " + range;
  };
  switch (read) {
    case IntRead::kWhole:
      return gemmi::cif::is_null(raw) ? "" : whole(raw);
    case IntRead::kSequenceId: {
      std::string s = gemmi::cif::as_string(raw);
      if (s.empty()) return "";
      if (s.back() >= 'A') {
        s.pop_back();  // the insertion code
      } else if (gemmi::cif::is_null(s)) {
        return "";
      }
      return whole(s);
    }
    case IntRead::kLeadingDigits: {
      std::size_t i = 0;
      bool digits = false;
      return leading_integer(raw, i, digits) ? "" : "starts with a number that is not " + range;
    }
    case IntRead::kOperators: {
      // parse_operation_expr, counting instead of listing.
      const std::string expr = gemmi::cif::as_string(raw);
      std::size_t start = 0, close = std::string::npos;
      if (!expr.empty() && expr[0] == '(') {
        start = 1;
        close = expr.find(')');
      }
      long long count = 0;
      for (;;) {
        const std::size_t sep = std::min(expr.find(',', start), close);
        const std::size_t minus = expr.find('-', start);
        if (minus < sep) {
          bool digits = false;
          std::size_t i = start, j = minus + 1;
          const auto low = leading_integer(expr, i, digits, false);
          const auto high = leading_integer(expr, j, digits, false);
          // gemmi counts up to the upper end with an int: INT_MAX would never stop.
          if (!low || !high || *high == kIntMax)
            return "has an operator number that is not an integer from 0 to " +
                   std::to_string(kIntMax - 1);
          if (*high >= *low) count += *high - *low + 1;
          if (count > kMaxAssemblyOperators)
            return "lists more than " + std::to_string(kMaxAssemblyOperators) + " operators";
        }
        if (sep == close) break;
        start = sep + 1;
      }
      return "";
    }
  }
  return "";
}

void require_readable_integers(gemmi::cif::Block& block, std::string_view text,
                               const std::string& name) {
  for (const IntColumn& column : kIntColumns) {
    gemmi::cif::Table table = block.find(column.category, {column.tag});
    for (const auto row : table) {
      const std::string& value = row[0];
      const std::string problem = int_problem(value, column.read);
      if (problem.empty()) continue;
      throw InputError(
          name, value_line(block, table, row.row_index, 0, text, value),
          value_label(column.category, column.tag, value, row.row_index) + " " + problem);
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
      require_readable_integers(doc.blocks.front(), text, name);
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
