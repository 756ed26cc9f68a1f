#include "molmesh/io/radius_table.hpp"

#include <cmath>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {

RadiusTable read_radius_table(const std::filesystem::path& path) {
  using namespace io_detail;
  const std::string name = path.string();
  const std::string text = read_file_contents(path);
  require_no_nul(text, name);
  RadiusTable table;
  table.source = name;
  LineCursor lines(text);
  std::vector<std::string_view> fields;
  while (next_content(lines, fields)) {
    const std::size_t n = lines.line_number();
    if (fields.size() != 2 && fields.size() != 3)
      throw InputError(name, n,
                       "expected 'RESNAME ATOMNAME radius' or 'ELEMENT radius', found " +
                           std::to_string(fields.size()) + " fields");
    const double radius = require_double(fields.back(), "radius", name, n);
    if (radius < 0.0)
      throw InputError(name, n, "radius must be >= 0, found " + std::string(fields.back()));
    bool inserted = false;
    if (fields.size() == 2) {
      inserted = table.by_element.emplace(to_upper(fields[0]), radius).second;
    } else {
      inserted =
          table.by_residue_atom.emplace(std::pair{to_upper(fields[0]), to_upper(fields[1])}, radius)
              .second;
    }
    if (!inserted) throw InputError(name, n, "duplicate entry (an earlier line has the same key)");
  }
  if (table.empty()) throw InputError(name, "radius table has no entries");
  return table;
}

}  // namespace molmesh
