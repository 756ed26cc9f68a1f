#pragma once
// Shared helpers for the readers: load a whole file (gunzipping .gz), walk its lines with
// line numbers, split fields and parse numbers strictly, so every reader reports errors
// the same way ("file:line: what").
#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh::io_detail {

// Whole file contents; transparently decompresses gzip data (detected by magic bytes).
// Throws InputError for missing, unreadable or corrupt-gzip files.
std::string read_file_contents(const std::filesystem::path& path);

// The extension that selects a format, lowercased, with a trailing ".gz" skipped:
// "x.PDB.gz" -> ".pdb".
std::string format_extension(const std::filesystem::path& path);

// Iterates lines (LF or CRLF), counting from 1.
class LineCursor {
 public:
  explicit LineCursor(std::string_view text) : text_(text) {}
  // False at the end of the text.
  bool next(std::string_view& line);
  std::size_t line_number() const { return line_number_; }
  // Bytes after the current line.
  std::size_t remaining() const { return pos_ < text_.size() ? text_.size() - pos_ : 0; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_number_ = 0;
};

// The readers' one idea of whitespace, the C locale's isspace set: space, \t, \r, \n, \v,
// \f. split_fields and trim both use it, so a line trim() calls non-blank always has a
// field (a line of form feeds was once non-blank to trim() but had no fields, and the MSMS
// reader took the first of none). Not std::isspace: that one follows the global locale.
constexpr bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Fields separated by runs of blanks (is_blank) and, when `commas`, commas.
std::vector<std::string_view> split_fields(std::string_view line, bool commas = false);

// The fields (split_fields) of the next line that has any once a '#' and what follows it
// are cut off: the comment rule of OFF, OBJ, DX, radius tables and sphere lists. False at
// the end of the text; lines.line_number() is then the line the fields came from.
bool next_content(LineCursor& lines, std::vector<std::string_view>& fields, bool commas = false);

// `s` without leading and trailing blanks (is_blank).
std::string_view trim(std::string_view s);

// Whole-field parses: nullopt unless the entire field is one finite number in plain
// decimal notation (an optional sign, digits, a point, an exponent). "nan", "inf", "1e400"
// (overflow), "0x10", "1,5", "1.5abc" and "" are not numbers: every reader takes its numbers
// from here, so none can misread such a field as data (docs/inputs.md, "Numbers").
std::optional<double> parse_double(std::string_view field);
std::optional<long long> parse_integer(std::string_view field);

// The same, throwing InputError at name:line: "WHAT 'field' is not a finite number" /
// "... is not an integer".
double require_double(std::string_view field, std::string_view what, const std::string& name,
                      std::size_t line);
long long require_integer(std::string_view field, std::string_view what, const std::string& name,
                          std::size_t line);

// A field as quoted in a message: "'abc'", cut to 40 characters so a megabyte-long token
// does not flood the terminal (control bytes are escaped by InputError itself).
std::string quoted(std::string_view field);

// The product of sample counts, or nullopt when it does not fit in size_t.
std::optional<std::size_t> checked_product(std::initializer_list<std::size_t> factors);

// How many of `count` announced items to reserve memory for: no more than `available` bytes
// can hold at `min_bytes` each. Readers reserve this and let the read itself report a short
// file at the line where it ends, so a header announcing 2^63 items costs nothing.
inline std::size_t reservable(std::size_t count, std::size_t min_bytes, std::size_t available) {
  return min_bytes == 0 ? 0 : std::min(count, available / min_bytes);
}

// Text formats carry no NUL bytes; one means binary data or a corrupt file (and would cut
// records short in parsers that stop at NUL). Throws InputError at the NUL's line.
void require_no_nul(std::string_view text, const std::string& name);

// Three finite numbers from fields[first..first+2] (a vertex's coordinates); throws
// InputError at `line` naming the offending field.
Vec3 parse_point(const std::vector<std::string_view>& fields, std::size_t first,
                 const std::string& name, std::size_t line);

// Appends the shortest text that reads back to exactly `value` (round-trip exact).
void append_number(std::string& out, double value);

// Appends "x y z" (round-trip exact).
void append_point(std::string& out, const Vec3& p);

// Text writers build their output in a string: this hands it to `out` once it passes 1 MB,
// so memory stays bounded for big meshes.
void flush_when_large(std::ostream& out, std::string& text);

// A mesh face with any number of corners, before triangulation.
// Fan-triangulates polygons (v0, vi, vi+1); throws InputError at `line` for fewer than 3
// corners or indices outside [0, vertex_count).
void append_polygon(const std::vector<long long>& corners, std::size_t vertex_count,
                    std::vector<std::array<int, 3>>& triangles, const std::string& name,
                    std::size_t line);

}  // namespace molmesh::io_detail
