#include "molmesh/io/msms.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

using namespace io_detail;

std::filesystem::path with_extension(std::filesystem::path p, const char* ext) {
  const std::string e = format_extension(p);
  if (e == ".vert" || e == ".face") p.replace_extension();
  p += ext;
  return p;
}

// MSMS writes comment lines ("# ...") and then one count line; the count is the first
// field of the first line that is not a comment.
template <typename Row>
void read_table(const std::filesystem::path& path, std::size_t min_fields, const char* what,
                Row&& row) {
  const std::string text = read_file_contents(path);
  const std::string name = path.string();
  require_no_nul(text, name);
  LineCursor lines(text);
  std::string_view line;
  long long expected = -1;
  long long seen = 0;
  while (lines.next(line)) {
    // Blank means "no fields": a line of form feeds or vertical tabs is blank too (front()
    // on its empty field list was undefined).
    const auto fields = split_fields(line);
    if (fields.empty() || fields.front().front() == '#') continue;
    if (expected < 0) {
      const auto count = parse_integer(fields.front());
      if (!count || *count < 0) {
        throw InputError(name, lines.line_number(),
                         std::string("expected the number of ") + what + " (MSMS header line)");
      }
      expected = *count;
      continue;
    }
    if (seen == expected) {
      throw InputError(name, lines.line_number(),
                       "more " + std::string(what) + " than the " + std::to_string(expected) +
                           " the header announces");
    }
    if (fields.size() < min_fields) {
      throw InputError(name, lines.line_number(),
                       "expected at least " + std::to_string(min_fields) + " fields, found " +
                           std::to_string(fields.size()));
    }
    row(fields, name, lines.line_number());
    ++seen;
  }
  if (expected < 0)
    throw InputError(name, std::string("no MSMS header with the number of ") + what);
  if (seen != expected) {
    throw InputError(name, "the header announces " + std::to_string(expected) + " " + what +
                               " but the file has " + std::to_string(seen));
  }
}

}  // namespace

bool is_msms_path(const std::filesystem::path& path) {
  const std::string e = format_extension(path);
  return e == ".vert" || e == ".face";
}

SurfaceMesh read_msms(const std::filesystem::path& path) {
  const auto vert = with_extension(path, ".vert");
  const auto face = with_extension(path, ".face");
  SurfaceMesh mesh;
  read_table(vert, 3, "vertices",
             [&](const std::vector<std::string_view>& f, const std::string& name,
                 std::size_t line) { mesh.points.push_back(parse_point(f, 0, name, line)); });
  read_table(
      face, 3, "faces",
      [&](const std::vector<std::string_view>& f, const std::string& name, std::size_t line) {
        std::vector<long long> corners(3);
        for (std::size_t i = 0; i < 3; ++i) {
          const long long v = require_integer(f[i], "vertex number", name, line);
          if (v < 1)
            throw InputError(name, line, "vertex numbers start at 1, found " + std::to_string(v));
          corners[i] = v - 1;  // MSMS counts from 1
        }
        append_polygon(corners, mesh.points.size(), mesh.triangles, name, line);
      });
  return mesh;
}

void write_msms(const std::filesystem::path& stem_or_either, const SurfaceMesh& mesh) {
  std::vector<Vec3> normals(mesh.points.size(), Vec3::Zero());
  for (const Triangle& t : mesh.triangles) {
    const Vec3 n =
        (mesh.points[static_cast<std::size_t>(t[1])] - mesh.points[static_cast<std::size_t>(t[0])])
            .cross(mesh.points[static_cast<std::size_t>(t[2])] -
                   mesh.points[static_cast<std::size_t>(t[0])]);
    for (int v : t) normals[static_cast<std::size_t>(v)] += n;
  }
  write_file_atomically(with_extension(stem_or_either, ".vert"), [&](std::ostream& out) {
    out << "# MSMS solvent excluded surface vertices (written by molmesh)\n"
        << "#vertex #sphere density probe_r\n"
        << mesh.points.size() << " 0 0.00 0.00\n";
    char buf[160];
    for (std::size_t v = 0; v < mesh.points.size(); ++v) {
      const Vec3& p = mesh.points[v];
      const double len = normals[v].norm();
      const Vec3 n = len > 0.0 ? Vec3(normals[v] / len) : Vec3::Zero();
      std::snprintf(buf, sizeof buf, "%12.6f %12.6f %12.6f %9.6f %9.6f %9.6f %7d %7d %2d\n", p.x(),
                    p.y(), p.z(), n.x(), n.y(), n.z(), 0, 0, 2);
      out << buf;
    }
  });
  write_file_atomically(with_extension(stem_or_either, ".face"), [&](std::ostream& out) {
    out << "# MSMS solvent excluded surface faces (written by molmesh)\n"
        << "#faces  #sphere density probe_r\n"
        << mesh.triangles.size() << " 0 0.00 0.00\n";
    for (const Triangle& t : mesh.triangles) {
      out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << " 1 0\n";
    }
  });
}

}  // namespace molmesh
