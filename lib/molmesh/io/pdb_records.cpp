#include "molmesh/io/pdb_records.hpp"

#include <cctype>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh::io_detail {
namespace {

bool is_digits(std::string_view s) {
  if (s.empty()) return false;
  for (const char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// What gemmi takes for a coordinate record: "ATOM" or "HETATM" at the start of the line.
// The line starts with `word` (upper case), ignoring case, as gemmi matches record names.
bool starts_with_record(std::string_view line, std::string_view word) {
  if (line.size() < word.size()) return false;
  for (std::size_t i = 0; i < word.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(line[i])) != word[i]) return false;
  return true;
}

// Whether gemmi's string_to_int would overflow an int reading `field`: blanks, a sign, then
// the digits it accumulates (it stops at the first other character).
bool int_field_overflows(std::string_view field) {
  std::size_t i = 0;
  // gemmi's blanks: space and the control characters 9-13.
  while (i < field.size() && (field[i] == ' ' || (field[i] >= '\t' && field[i] <= '\r'))) ++i;
  if (i < field.size() && (field[i] == '-' || field[i] == '+')) ++i;
  long long value = 0;
  for (; i < field.size() && field[i] >= '0' && field[i] <= '9'; ++i) {
    value = value * 10 + (field[i] - '0');
    if (value > std::numeric_limits<int>::max()) return true;
  }
  return false;
}

// What gemmi reads as an atom: it tells records apart by their first four letters, so
// "HETAxx" is a HETATM record to it (the pdb fuzz campaign: "HETATILEM" carried an infinite
// coordinate past this check when it asked for all six letters).
bool is_coordinate_record(std::string_view line) {
  return starts_with_record(line, "HETA") || starts_with_record(line, "ATOM");
}

// Whether columns 31-38, 39-46, 47-54 hold three finite numbers.
bool fixed_columns_parse(std::string_view line) {
  // A tab before column 55 shifts the columns; one after them (seen in hand-edited files)
  // does not.
  if (line.size() < 54 || line.substr(0, 54).find('\t') != std::string_view::npos) return false;
  for (std::size_t k = 0; k < 3; ++k)
    if (!parse_double(trim(line.substr(30 + 8 * k, 8)))) return false;
  return true;
}

// `token` right-aligned in `width` columns; a number too wide is reformatted with
// `decimals` places. False if it cannot fit.
bool put_right(std::string& out, std::string_view token, std::size_t width, int decimals = -1) {
  std::string text(token);
  if (text.size() > width && decimals >= 0) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, *parse_double(token));
    text = buffer;
  }
  if (text.size() > width) return false;
  out.append(width - text.size(), ' ').append(text);
  return true;
}

// The record rebuilt in fixed columns from whitespace-separated fields
// "ATOM serial name resname [chain] resseq x y z [occupancy [B]] [element]", or nullopt.
std::optional<std::string> rewrite_from_fields(std::string_view line) {
  const auto fields = split_fields(line);
  std::vector<std::string_view> tokens;
  const std::string_view record =
      std::toupper(static_cast<unsigned char>(line[0])) == 'H' ? "HETATM" : "ATOM";
  // The record name may touch the serial ("HETATM12345").
  if (fields[0].size() > record.size()) tokens.push_back(fields[0].substr(record.size()));
  for (std::size_t i = 1; i < fields.size(); ++i) tokens.push_back(fields[i]);
  // Coordinates: the first three consecutive decimal numbers (serials and residue numbers
  // are integers, names are words).
  auto decimal = [&](std::size_t i) {
    return i < tokens.size() && tokens[i].find('.') != std::string_view::npos &&
           parse_double(tokens[i]).has_value();
  };
  std::size_t c = 0;
  while (c < tokens.size() && !(decimal(c) && decimal(c + 1) && decimal(c + 2))) ++c;
  if (c >= tokens.size() || (c != 4 && c != 5)) return std::nullopt;
  const std::string_view serial = tokens[0], atom = tokens[1], residue = tokens[2];
  const std::string_view chain = c == 5 ? tokens[3] : std::string_view();
  std::string_view resseq = tokens[c - 1];
  std::string_view insertion;
  if (!resseq.empty() && std::isalpha(static_cast<unsigned char>(resseq.back()))) {
    insertion = resseq.substr(resseq.size() - 1);
    resseq.remove_suffix(1);
  }
  if (!is_digits(serial) || !is_digits(resseq) || atom.size() > 4 || residue.size() > 4 ||
      chain.size() > 1)
    return std::nullopt;

  std::string out(record);
  out.append(6 - record.size(), ' ');
  if (!put_right(out, serial, 5)) return std::nullopt;
  out += ' ';
  // Names shorter than 4 start in column 14, where the element symbol is expected.
  std::string name_columns = atom.size() < 4 ? " " + std::string(atom) : std::string(atom);
  name_columns.resize(4, ' ');
  out += name_columns;
  out += ' ';  // altloc
  if (!put_right(out, residue, residue.size() == 4 ? 4 : 3)) return std::nullopt;
  if (residue.size() != 4) out += ' ';
  out += chain.empty() ? ' ' : chain[0];
  if (!put_right(out, resseq, 4)) return std::nullopt;
  out += insertion.empty() ? ' ' : insertion[0];
  out += "   ";
  for (std::size_t k = 0; k < 3; ++k)
    if (!put_right(out, tokens[c + k], 8, 3)) return std::nullopt;
  // Then occupancy and B factor if numbers, and an element symbol if one follows.
  std::size_t i = c + 3;
  std::string_view occupancy = "1.00", bfactor = "0.00", element;
  if (i < tokens.size() && parse_double(tokens[i])) occupancy = tokens[i++];
  if (i < tokens.size() && parse_double(tokens[i])) bfactor = tokens[i++];
  if (i < tokens.size() && tokens[i].size() <= 2 &&
      std::isalpha(static_cast<unsigned char>(tokens[i][0])) &&
      (tokens[i].size() == 1 || std::isalpha(static_cast<unsigned char>(tokens[i][1]))))
    element = tokens[i];
  if (!put_right(out, occupancy, 6, 2) || !put_right(out, bfactor, 6, 2)) return std::nullopt;
  out.append(10, ' ');
  put_right(out, element, 2);
  return out;
}

}  // namespace

PdbScan scan_pdb_records(const std::string& contents, const std::string& name) {
  PdbScan scan;
  std::string rewritten;
  std::size_t copied = 0;  // contents[0, copied) are in `rewritten`
  bool changed = false;
  LineCursor cursor(contents);
  std::string_view line;
  // Puts `text` in place of the current line in the text gemmi reads.
  auto replace = [&](std::string_view text) {
    const auto offset = static_cast<std::size_t>(line.data() - contents.data());
    rewritten.append(contents, copied, offset - copied).append(text);
    copied = offset + line.size();
    changed = true;
  };
  // Three guards for gemmi 0.5 (Debian 12), all found by fuzzing (tests/fuzz/crashes/pdb):
  // it reads columns 74-78 of an SSBOND/LINK record past the end of a shorter line, so those
  // are padded to 80 columns; it ignores a line beyond column 120 but, at a byte >= 0x80
  // there, starts a new record after it, so lines are cut at 120 columns (what it reads);
  // and it reads a DBREF2 record's database positions (columns 46-55, 58-67) as 10-digit
  // ints without an overflow check (undefined behaviour), so such records are padded to 80
  // columns and a value beyond an int is blanked (molmesh reads nothing of DBREF).
  constexpr std::size_t gemmi_columns = 120;
  auto guard_for_gemmi = [&] {
    const std::string_view visible = line.substr(0, gemmi_columns);
    // gemmi tells records apart by their first four letters only.
    const bool short_bond = visible.size() < 80 && (starts_with_record(visible, "SSBO") ||
                                                    starts_with_record(visible, "LINK"));
    const bool dbref2 =
        starts_with_record(visible, "DBRE") && visible.size() > 5 && visible[5] == '2';
    if (!short_bond && !dbref2) {
      if (visible.size() < line.size()) replace(visible);
      return;
    }
    // Both padded: past the end of a shorter line gemmi reads what an earlier, longer line
    // left in its buffer.
    std::string safe(visible);
    if (safe.size() < 80) safe.resize(80, ' ');
    if (dbref2)
      for (const std::size_t column : {std::size_t{45}, std::size_t{57}})
        if (int_field_overflows(std::string_view(safe).substr(column, 10)))
          safe.replace(column, 10, 10, ' ');
    if (safe != line) replace(safe);
  };
  while (cursor.next(line)) {
    if (!is_coordinate_record(line)) {
      guard_for_gemmi();
      continue;
    }
    const std::size_t n = cursor.line_number();
    if (!fixed_columns_parse(line)) {
      const auto fixed = rewrite_from_fields(line);
      if (!fixed) {
        // Neither layout: report the fixed columns, as a PDB reader would.
        if (line.size() < 54)
          throw InputError(name, n,
                           "ATOM/HETATM record too short for coordinates (columns 31-54), and "
                           "not 'ATOM serial name resname [chain] resseq x y z' either");
        for (std::size_t k = 0; k < 3; ++k) {
          const std::string_view column = trim(line.substr(30 + 8 * k, 8));
          if (!parse_double(column))
            throw InputError(name, n,
                             std::string(1, "xyz"[k]) + " coordinate " + quoted(column) +
                                 " (columns " + std::to_string(31 + 8 * k) + "-" +
                                 std::to_string(38 + 8 * k) + ") is not a finite number");
        }
        throw InputError(name, n, "tab in an ATOM/HETATM record whose fields cannot be read");
      }
      replace(*fixed);
      if (scan.whitespace_records++ == 0) scan.first_whitespace_line = n;
      const auto serial = parse_integer(trim(std::string_view(*fixed).substr(6, 5)));
      if (serial) scan.lines.emplace(static_cast<int>(*serial), n);
      continue;
    }
    guard_for_gemmi();
    const auto serial = parse_integer(trim(line.substr(6, 5)));
    if (serial) scan.lines.emplace(static_cast<int>(*serial), n);
  }
  if (changed) {
    rewritten.append(contents, copied, std::string::npos);
    scan.rewritten = std::move(rewritten);
  }
  return scan;
}

}  // namespace molmesh::io_detail
