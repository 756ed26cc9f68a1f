#include "molmesh/io/sphere_list.hpp"

#include <cmath>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {

std::vector<Sphere> read_spheres(const std::filesystem::path& path) {
  using namespace io_detail;
  const std::string name = path.string();
  const std::string text = read_file_contents(path);
  require_no_nul(text, name);
  std::vector<Sphere> spheres;
  LineCursor lines(text);
  std::vector<std::string_view> f;
  while (next_content(lines, f, true)) {
    const std::size_t n = lines.line_number();
    if (f.size() != 4)
      throw InputError(
          name, n,
          "expected 'x y z radius' (4 numbers), found " + std::to_string(f.size()) + " fields");
    double v[4];
    static constexpr const char* kWhat[4] = {"x", "y", "z", "radius"};
    for (std::size_t k = 0; k < 4; ++k) v[k] = require_double(f[k], kWhat[k], name, n);
    if (v[3] < 0.0) throw InputError(name, n, "negative sphere radius " + std::string(f[3]));
    spheres.push_back({Vec3(v[0], v[1], v[2]), v[3]});
  }
  if (spheres.empty()) throw InputError(name, "no spheres (expected lines 'x y z radius')");
  return spheres;
}

}  // namespace molmesh
