#include "molmesh/io/text_input.hpp"

#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>

#include "molmesh/core/error.hpp"

namespace molmesh::io_detail {
namespace {

bool is_gzip(const std::string& bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string gunzip(const std::string& bytes, const std::string& name) {
  z_stream stream{};
  // 16 + MAX_WBITS: expect a gzip header; concatenated members are handled by the loop.
  if (inflateInit2(&stream, 16 + MAX_WBITS) != Z_OK)
    throw InputError(name, "cannot initialise gzip decompression");
  std::string out;
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  char buffer[1 << 16];
  int status = Z_OK;
  while (true) {
    stream.next_out = reinterpret_cast<Bytef*>(buffer);
    stream.avail_out = sizeof buffer;
    status = inflate(&stream, Z_NO_FLUSH);
    if (status != Z_OK && status != Z_STREAM_END) break;
    out.append(buffer, sizeof buffer - stream.avail_out);
    if (status == Z_STREAM_END) {
      if (stream.avail_in == 0) break;
      inflateReset(&stream);  // another gzip member follows
    }
  }
  inflateEnd(&stream);
  if (status != Z_STREAM_END)
    throw InputError(name, "corrupt or truncated gzip data (try: gzip -t " + name + ")");
  return out;
}

}  // namespace

std::string read_file_contents(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(name, "no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(name, "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(name, "cannot open for reading (check permissions)");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError(name, "read error");
  if (is_gzip(bytes)) return gunzip(bytes, name);
  return bytes;
}

std::string format_extension(const std::filesystem::path& path) {
  auto lower = [](std::string s) {
    std::transform(s.begin(), s.end(), s.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return s;
  };
  std::string ext = lower(path.extension().string());
  if (ext == ".gz") ext = lower(path.stem().extension().string());
  return ext;
}

bool LineCursor::next(std::string_view& line) {
  if (pos_ >= text_.size()) return false;
  const std::size_t end = text_.find('\n', pos_);
  const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
  line = text_.substr(pos_, stop - pos_);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  pos_ = stop + 1;
  ++line_number_;
  return true;
}

std::vector<std::string_view> split_fields(std::string_view line, bool commas) {
  std::vector<std::string_view> fields;
  auto separator = [commas](char c) { return is_blank(c) || (commas && c == ','); };
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && separator(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !separator(line[i])) ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

bool next_content(LineCursor& lines, std::vector<std::string_view>& fields, bool commas) {
  std::string_view line;
  while (lines.next(line)) {
    if (const auto hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    fields = split_fields(line, commas);
    if (!fields.empty()) return true;
  }
  return false;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
  return s;
}

std::optional<double> parse_double(std::string_view field) {
  // from_chars rejects a leading '+', which some writers emit (but not "+-1" or "+").
  if (!field.empty() && field.front() == '+') {
    field.remove_prefix(1);
    if (field.empty() || field.front() == '+' || field.front() == '-') return std::nullopt;
  }
  double value = 0.0;
  // General format: no hex; "1e400" gives result_out_of_range.
  const auto [end, ec] =
      std::from_chars(field.data(), field.data() + field.size(), value, std::chars_format::general);
  if (ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
  // from_chars reads "nan" and "inf" as numbers; data never holds them.
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<long long> parse_integer(std::string_view field) {
  if (!field.empty() && field.front() == '+') {
    field.remove_prefix(1);
    if (field.empty() || field.front() == '-') return std::nullopt;
  }
  long long value = 0;
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (ec != std::errc() || end != field.data() + field.size()) return std::nullopt;
  return value;
}

std::string quoted(std::string_view field) {
  constexpr std::size_t kMax = 40;
  if (field.size() <= kMax) return "'" + std::string(field) + "'";
  return "'" + std::string(field.substr(0, kMax)) + "...' (" + std::to_string(field.size()) +
         " characters)";
}

double require_double(std::string_view field, std::string_view what, const std::string& name,
                      std::size_t line) {
  const auto value = parse_double(field);
  if (!value)
    throw InputError(name, line,
                     std::string(what) + " " + quoted(field) + " is not a finite number");
  return *value;
}

long long require_integer(std::string_view field, std::string_view what, const std::string& name,
                          std::size_t line) {
  const auto value = parse_integer(field);
  if (!value)
    throw InputError(name, line, std::string(what) + " " + quoted(field) + " is not an integer");
  return *value;
}

std::optional<std::size_t> checked_product(std::initializer_list<std::size_t> factors) {
  std::size_t product = 1;
  for (const std::size_t f : factors)
    if (__builtin_mul_overflow(product, f, &product)) return std::nullopt;
  return product;
}

void require_no_nul(std::string_view text, const std::string& name) {
  const std::size_t nul = text.find('\0');
  if (nul == std::string_view::npos) return;
  const auto line = static_cast<std::size_t>(std::count(
                        text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n')) +
                    1;
  throw InputError(
      name, line,
      "NUL byte in a text file (binary data or a corrupt file; byte " + std::to_string(nul) + ")");
}

void append_number(std::string& out, double value) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, ec == std::errc() ? end : buffer);
}

void append_point(std::string& out, const Vec3& p) {
  append_number(out, p.x());
  out += ' ';
  append_number(out, p.y());
  out += ' ';
  append_number(out, p.z());
}

void flush_when_large(std::ostream& out, std::string& text) {
  if (text.size() > (1 << 20)) {
    out << text;
    text.clear();
  }
}

Vec3 parse_point(const std::vector<std::string_view>& fields, std::size_t first,
                 const std::string& name, std::size_t line) {
  Vec3 p;
  for (std::size_t k = 0; k < 3; ++k)
    p[static_cast<Eigen::Index>(k)] = require_double(fields[first + k], "coordinate", name, line);
  return p;
}

void append_polygon(const std::vector<long long>& corners, std::size_t vertex_count,
                    std::vector<std::array<int, 3>>& triangles, const std::string& name,
                    std::size_t line) {
  if (corners.size() < 3)
    throw InputError(name, line,
                     "face has " + std::to_string(corners.size()) + " corners (at least 3 needed)");
  for (const long long c : corners) {
    if (c < 0 || static_cast<unsigned long long>(c) >= vertex_count)
      throw InputError(name, line,
                       "vertex index " + std::to_string(c) + " out of range (the file has " +
                           std::to_string(vertex_count) + " vertices)");
  }
  for (std::size_t i = 1; i + 1 < corners.size(); ++i)
    triangles.push_back({static_cast<int>(corners[0]), static_cast<int>(corners[i]),
                         static_cast<int>(corners[i + 1])});
}

}  // namespace molmesh::io_detail
