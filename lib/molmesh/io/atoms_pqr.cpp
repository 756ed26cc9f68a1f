#include "molmesh/io/atoms_pqr.hpp"

#include <cctype>
#include <cmath>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

using io_detail::parse_double;

constexpr const char* kLayout =
    "expected 'ATOM serial name resname [chain] resnum x y z charge radius'";

bool is_alpha(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; }
bool is_digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// "-12.345-6.789" -> {"-12.345", "-6.789"}: fixed-column writers leave no blank before a
// negative number that fills its column. Only splits when every piece is a number, so
// names containing '-' are left alone; an exponent's sign ("1e-5") is not a boundary.
void append_unglued(std::string_view token, std::vector<std::string_view>& out) {
  std::vector<std::string_view> pieces;
  std::size_t start = 0;
  for (std::size_t i = 1; i < token.size(); ++i) {
    if (token[i] == '-' && (is_digit(token[i - 1]) || token[i - 1] == '.')) {
      pieces.push_back(token.substr(start, i - start));
      start = i;
    }
  }
  if (pieces.empty()) {
    out.push_back(token);
    return;
  }
  pieces.push_back(token.substr(start));
  for (auto piece : pieces) {
    if (!parse_double(piece)) {
      out.push_back(token);
      return;
    }
  }
  out.insert(out.end(), pieces.begin(), pieces.end());
}

struct ResidueNumber {
  std::string chain;  // letters glued in front ("A1000"), if any
  int number = 0;
  bool ok = false;
};

// Accepts "[chain]-?digits[insertion code]".
ResidueNumber parse_residue_number(std::string_view token) {
  ResidueNumber r;
  std::size_t i = 0;
  while (i < token.size() && is_alpha(token[i])) ++i;
  r.chain = std::string(token.substr(0, i));
  std::size_t j = i;
  if (j < token.size() && token[j] == '-') ++j;
  const std::size_t digits_start = j;
  while (j < token.size() && is_digit(token[j])) ++j;
  if (j == digits_start || j - digits_start > 9) return r;
  std::size_t k = j;
  if (k < token.size() && is_alpha(token[k])) ++k;  // insertion code: not kept
  if (k != token.size()) return r;
  r.number = static_cast<int>(*io_detail::parse_integer(token.substr(i, j - i)));
  r.ok = true;
  return r;
}

Atom parse_record(std::string_view line, const std::string& name, std::size_t n) {
  auto fields = io_detail::split_fields(line);
  Atom atom;
  std::vector<std::string_view> tokens;
  std::string_view record = fields[0];
  // "HETATM12345": the serial fills its columns and touches the record name.
  const std::string_view prefix = record.substr(0, 6) == "HETATM" ? "HETATM" : "ATOM";
  atom.hetatm = prefix == "HETATM";
  if (record.size() > prefix.size()) tokens.push_back(record.substr(prefix.size()));
  for (std::size_t i = 1; i < fields.size(); ++i) append_unglued(fields[i], tokens);

  // Trailing non-numeric columns (element symbol, segment id) are extras, not data.
  std::size_t end = tokens.size();
  while (end > 0 && !parse_double(tokens[end - 1])) --end;
  if (end < tokens.size()) {
    const auto extra = tokens[end];
    if (extra.size() <= 2 && is_alpha(extra[0]) && (extra.size() == 1 || is_alpha(extra[1])))
      atom.element = std::string(extra);
  }
  if (end < 5 + 4) {
    // Enough fields, but the trailing ones are words: a bad number ("nan"), not an extra.
    if (tokens.size() >= 5 + 4)
      throw InputError(name, n,
                       io_detail::quoted(tokens[end]) + " is not a finite number; " + kLayout);
    throw InputError(name, n, std::string("too few fields for a PQR atom; ") + kLayout);
  }
  // The last five numbers are x y z charge radius; each must be one: a word among them is
  // an error, never skipped (a skip would shift a neighbour's value into its place).
  static constexpr const char* kColumn[5] = {"x coordinate", "y coordinate", "z coordinate",
                                             "charge", "radius"};
  double values[5];
  for (std::size_t i = 0; i < 5; ++i)
    values[i] = io_detail::require_double(tokens[end - 5 + i], kColumn[i], name, n);
  const std::size_t head = end - 5;  // tokens[0..head): serial, names, residue number

  const ResidueNumber resnum = parse_residue_number(tokens[head - 1]);
  if (!resnum.ok)
    throw InputError(
        name, n,
        "residue number '" + std::string(tokens[head - 1]) + "' is not an integer; " + kLayout);
  const std::size_t middle = head - 2;  // fields between serial and residue number
  if (middle < 2 || middle > 3)
    throw InputError(name, n,
                     "cannot tell atom name, residue name and chain apart (" +
                         std::to_string(middle) + " fields before the residue number); " + kLayout);
  atom.atom_name = std::string(tokens[1]);
  atom.residue_name = std::string(tokens[2]);
  if (middle == 3) {
    if (!resnum.chain.empty())
      throw InputError(name, n,
                       "two chain identifiers ('" + std::string(tokens[3]) + "' and '" +
                           resnum.chain + "'); " + kLayout);
    atom.chain = std::string(tokens[3]);
  } else {
    atom.chain = resnum.chain;
  }
  atom.residue_number = resnum.number;
  atom.center = Vec3(values[0], values[1], values[2]);
  atom.charge = values[3];
  atom.radius = values[4];

  if (atom.radius < 0.0)
    throw InputError(name, n,
                     "negative radius " + std::string(tokens[end - 1]) +
                         " (radii must be >= 0; 0 means the atom adds no volume)");
  return atom;
}

bool is_atom_record(std::string_view first_field) {
  auto digits_after = [&](std::size_t k) {
    for (std::size_t i = k; i < first_field.size(); ++i)
      if (!is_digit(first_field[i])) return false;
    return true;
  };
  if (first_field.substr(0, 6) == "HETATM") return digits_after(6);
  if (first_field.substr(0, 4) == "ATOM") return digits_after(4);
  return false;
}

}  // namespace

Atoms parse_pqr(std::string_view text, const std::string& name, const Reporter& reporter) {
  io_detail::require_no_nul(text, name);
  Atoms atoms;
  io_detail::LineCursor lines(text);
  std::string_view line;
  bool first_model_done = false;
  std::size_t later_model_atoms = 0;
  while (lines.next(line)) {
    const auto fields = io_detail::split_fields(line);
    if (fields.empty()) continue;
    if (fields[0] == "ENDMDL") {
      if (!atoms.empty()) first_model_done = true;
      continue;
    }
    if (!is_atom_record(fields[0])) continue;
    if (first_model_done) {
      ++later_model_atoms;
      continue;
    }
    atoms.push_back(parse_record(line, name, lines.line_number()));
  }
  if (later_model_atoms > 0)
    reporter.warn(name + ": only the first MODEL is used (" + std::to_string(later_model_atoms) +
                  " atom records of later models ignored)");
  return atoms;
}

}  // namespace molmesh
