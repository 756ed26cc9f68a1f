#include "molmesh/io/mesh_off.hpp"

#include <cmath>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

using namespace io_detail;

long long count_field(std::string_view field, const std::string& name, std::size_t line,
                      const char* what) {
  const auto value = parse_integer(field);
  if (!value || *value < 0)
    throw InputError(
        name, line,
        std::string(what) + " '" + std::string(field) + "' is not a non-negative integer");
  return *value;
}

}  // namespace

SurfaceMesh parse_off(std::string_view text, const std::string& name) {
  require_no_nul(text, name);
  LineCursor lines(text);
  std::vector<std::string_view> fields;
  if (!next_content(lines, fields)) throw InputError(name, "empty file: no OFF header");
  const std::string_view keyword = fields[0];
  if (keyword.size() < 3 || keyword.substr(keyword.size() - 3) != "OFF")
    throw InputError(
        name, lines.line_number(),
        "not an OFF file: the first line must be 'OFF', found '" + std::string(keyword) + "'");
  if (keyword.find("4") != std::string_view::npos || keyword.find("n") != std::string_view::npos)
    throw InputError(name, lines.line_number(),
                     "only 3D OFF is supported, found " + std::string(keyword));
  fields.erase(fields.begin());
  if (fields.empty() && !next_content(lines, fields))
    throw InputError(name, lines.line_number(), "missing the 'vertices faces edges' counts");
  if (fields.size() < 2)
    throw InputError(name, lines.line_number(), "expected 'vertices faces edges' counts");
  const std::size_t counts_line = lines.line_number();
  const auto nv =
      static_cast<std::size_t>(count_field(fields[0], name, counts_line, "vertex count"));
  const auto nf = static_cast<std::size_t>(count_field(fields[1], name, counts_line, "face count"));

  // A vertex line holds 3 fields of >= 2 bytes with their separators: never reserve more
  // than the file can hold (a count of 2^63 used to throw length_error, exit 70).
  SurfaceMesh mesh;
  mesh.points.reserve(reservable(nv, 6, lines.remaining()));
  for (std::size_t i = 0; i < nv; ++i) {
    if (!next_content(lines, fields))
      throw InputError(
          name, lines.line_number(),
          "file ends after " + std::to_string(i) + " of " + std::to_string(nv) + " vertices");
    if (fields.size() < 3) throw InputError(name, lines.line_number(), "expected 'x y z'");
    mesh.points.push_back(parse_point(fields, 0, name, lines.line_number()));
  }
  std::vector<long long> corners;
  for (std::size_t f = 0; f < nf; ++f) {
    if (!next_content(lines, fields))
      throw InputError(
          name, lines.line_number(),
          "file ends after " + std::to_string(f) + " of " + std::to_string(nf) + " faces");
    const std::size_t n = lines.line_number();
    const auto count = count_field(fields[0], name, n, "face corner count");
    if (fields.size() < static_cast<std::size_t>(count) + 1)
      throw InputError(name, n,
                       "face announces " + std::to_string(count) + " corners but has " +
                           std::to_string(fields.size() - 1));
    corners.clear();
    for (long long c = 1; c <= count; ++c) {
      const auto index = parse_integer(fields[static_cast<std::size_t>(c)]);
      if (!index)
        throw InputError(name, n,
                         "vertex index '" + std::string(fields[static_cast<std::size_t>(c)]) +
                             "' is not an integer");
      corners.push_back(*index);
    }
    append_polygon(corners, nv, mesh.triangles, name, n);
  }
  return mesh;
}

void write_off(std::ostream& out, const SurfaceMesh& mesh) {
  std::string text = "OFF\n" + std::to_string(mesh.points.size()) + " " +
                     std::to_string(mesh.triangles.size()) + " 0\n";
  for (const Vec3& p : mesh.points) {
    append_point(text, p);
    text += '\n';
    flush_when_large(out, text);
  }
  for (const Triangle& t : mesh.triangles) {
    text += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) +
            "\n";
    flush_when_large(out, text);
  }
  out << text;
}

}  // namespace molmesh
