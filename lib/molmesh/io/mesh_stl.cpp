#include "molmesh/io/mesh_stl.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

using namespace io_detail;

class VertexMerger {
 public:
  explicit VertexMerger(SurfaceMesh& mesh) : mesh_(mesh) {}
  int add(const Vec3& p) {
    const auto [it, inserted] =
        index_.try_emplace({p.x(), p.y(), p.z()}, static_cast<int>(mesh_.points.size()));
    if (inserted) mesh_.points.push_back(p);
    return it->second;
  }

 private:
  SurfaceMesh& mesh_;
  // Exact comparison on purpose: merging by tolerance would weld distinct close vertices.
  std::map<std::array<double, 3>, int> index_;
};

bool looks_binary(const std::string& bytes) {
  if (bytes.size() < 84) return false;
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  return bytes.size() == 84 + 50 * static_cast<std::size_t>(count);
}

SurfaceMesh parse_binary(const std::string& bytes, const std::string& name) {
  std::uint32_t count = 0;
  std::memcpy(&count, bytes.data() + 80, 4);
  SurfaceMesh mesh;
  VertexMerger merger(mesh);
  mesh.triangles.reserve(count);
  for (std::uint32_t f = 0; f < count; ++f) {
    const char* record = bytes.data() + 84 + 50 * static_cast<std::size_t>(f);
    Triangle t{};
    for (int c = 0; c < 3; ++c) {
      float xyz[3];
      std::memcpy(xyz, record + 12 + 12 * c, 12);
      const Vec3 p(xyz[0], xyz[1], xyz[2]);
      if (!p.allFinite())
        throw InputError(name, "triangle " + std::to_string(f) + " has a non-finite corner");
      t[static_cast<std::size_t>(c)] = merger.add(p);
    }
    mesh.triangles.push_back(t);
  }
  return mesh;
}

SurfaceMesh parse_ascii(const std::string& text, const std::string& name) {
  require_no_nul(text, name);
  SurfaceMesh mesh;
  VertexMerger merger(mesh);
  LineCursor lines(text);
  std::string_view line;
  std::vector<int> corners;
  std::size_t facet_line = 0;
  bool solid = false;
  bool open = false;  // inside solid ... endsolid: a file cut at a facet boundary stays open
  while (lines.next(line)) {
    const auto f = split_fields(line);
    if (f.empty()) continue;
    const std::size_t n = lines.line_number();
    if (f[0] == "solid") {
      if (open) throw InputError(name, n, "'solid' inside another solid (missing endsolid?)");
      solid = open = true;
    } else if (!open) {
      throw InputError(name, n, "'" + std::string(f[0]) + "' outside solid ... endsolid");
    } else if (f[0] == "facet") {
      if (facet_line != 0)
        throw InputError(name, n, "'facet' inside another facet (missing endfacet)");
      facet_line = n;
      corners.clear();
    } else if (f[0] == "vertex") {
      if (facet_line == 0) throw InputError(name, n, "'vertex' outside a facet");
      if (f.size() != 4) throw InputError(name, n, "expected 'vertex x y z'");
      corners.push_back(merger.add(parse_point(f, 1, name, n)));
    } else if (f[0] == "endfacet") {
      if (facet_line == 0) throw InputError(name, n, "'endfacet' without 'facet'");
      if (corners.size() != 3)
        throw InputError(
            name, facet_line,
            "facet has " + std::to_string(corners.size()) + " vertices (STL facets are triangles)");
      mesh.triangles.push_back({corners[0], corners[1], corners[2]});
      facet_line = 0;
    } else if (f[0] == "endsolid") {
      if (facet_line != 0) throw InputError(name, facet_line, "facet not closed before 'endsolid'");
      open = false;
    } else if (f[0] == "outer" || f[0] == "endloop") {
      // structure only
    } else {
      throw InputError(name, n, "unexpected '" + std::string(f[0]) + "' in ascii STL");
    }
  }
  if (!solid) throw InputError(name, 1, "not an STL file (no 'solid' line, wrong size for binary)");
  if (facet_line != 0) throw InputError(name, facet_line, "facet not closed (file truncated?)");
  if (open)
    throw InputError(name, lines.line_number(),
                     "ascii STL ends without 'endsolid' (file truncated?)");
  return mesh;
}

}  // namespace

SurfaceMesh parse_stl(const std::string& bytes, const std::string& name) {
  static_assert(std::endian::native == std::endian::little, "STL is little endian");
  // Binary files may start with "solid" too; a size that matches the count decides.
  if (looks_binary(bytes)) return parse_binary(bytes, name);
  if (bytes.compare(0, 5, "solid") == 0) return parse_ascii(bytes, name);
  if (bytes.size() >= 84) {
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    throw InputError(name, "binary STL announces " + std::to_string(count) + " triangles (" +
                               std::to_string(84 + 50 * static_cast<std::size_t>(count)) +
                               " bytes) but the file has " + std::to_string(bytes.size()) +
                               " bytes (truncated?)");
  }
  throw InputError(name, "not an STL file (too short for binary, no 'solid' line)");
}

void write_stl(std::ostream& out, const SurfaceMesh& mesh) {
  std::string data(80, ' ');
  const std::string title = "binary STL written by molmesh";
  data.replace(0, title.size(), title);
  const auto count = static_cast<std::uint32_t>(mesh.triangles.size());
  data.append(reinterpret_cast<const char*>(&count), 4);
  for (const Triangle& t : mesh.triangles) {
    const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
    Vec3 normal = (b - a).cross(c - a);
    const double length = normal.norm();
    normal = length > 0.0 ? Vec3(normal / length) : Vec3::Zero();
    float record[12];
    for (int k = 0; k < 3; ++k) {
      record[k] = static_cast<float>(normal[k]);
      record[3 + k] = static_cast<float>(a[k]);
      record[6 + k] = static_cast<float>(b[k]);
      record[9 + k] = static_cast<float>(c[k]);
    }
    data.append(reinterpret_cast<const char*>(record), sizeof record);
    data.append(2, '\0');  // attribute byte count
    if (data.size() > (1 << 20)) {
      out.write(data.data(), static_cast<std::streamsize>(data.size()));
      data.clear();
    }
  }
  out.write(data.data(), static_cast<std::streamsize>(data.size()));
}

}  // namespace molmesh
