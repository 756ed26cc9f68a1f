#include "molmesh/io/volume_dx.hpp"

#include <cmath>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {

using namespace io_detail;

Grid parse_dx(std::string_view text, const std::string& name) {
  require_no_nul(text, name);
  LineCursor lines(text);
  Grid grid;
  bool have_counts = false, have_origin = false, have_data = false;
  int deltas = 0;
  std::size_t counts_line = 0, origin_line = 0, data_line = 0;
  std::size_t expected = 0;
  // One grid per file: a second gridpositions object after the data gave a grid whose
  // counts no longer matched its values (and a second origin or array would silently
  // replace the first).
  auto once = [&](std::size_t first, const char* what, std::size_t n) {
    if (first != 0)
      throw InputError(name, n,
                       std::string("a second ") + what + " (the first is on line " +
                           std::to_string(first) + "); one grid per file");
  };
  std::vector<std::string_view> f;
  while (next_content(lines, f)) {
    const std::size_t n = lines.line_number();
    // A line of numbers outside the data array used to be skipped like an unknown keyword.
    // After the data they are more values than `items` (the loop below stops at the
    // count); before it they belong to no object (a fourth delta, an origin without its
    // keyword, values ahead of their array), and reading on would leave the grid's
    // geometry or data other than the file meant.
    if (parse_double(f[0])) {
      if (have_data)
        throw InputError(name, n,
                         "more values than the " + std::to_string(expected) +
                             " items declared on line " + std::to_string(data_line));
      throw InputError(name, n,
                       "values before the data array: numbers belong after an 'object N class "
                       "array ... data follows' line, and header lines start with their keyword "
                       "('origin x y z', 'delta dx dy dz')");
    }
    if (f[0] == "object" && f.size() >= 4 && f[2] == "class" && f[3] == "gridpositions") {
      if (f.size() != 8 || f[4] != "counts")
        throw InputError(name, n, "expected 'object 1 class gridpositions counts nx ny nz'");
      once(counts_line, "gridpositions object", n);
      for (int k = 0; k < 3; ++k) {
        const auto c = parse_integer(f[static_cast<std::size_t>(5 + k)]);
        if (!c || *c < 1 || *c > 1000000)
          throw InputError(name, n,
                           "grid count '" + std::string(f[static_cast<std::size_t>(5 + k)]) +
                               "' is not a positive integer");
        grid.dims[static_cast<std::size_t>(k)] = static_cast<int>(*c);
      }
      have_counts = true;
      counts_line = n;
    } else if (f[0] == "origin" || f[0] == "delta") {
      if (f.size() != 4) throw InputError(name, n, "expected '" + std::string(f[0]) + " x y z'");
      const Vec3 v = parse_point(f, 1, name, n);
      if (f[0] == "origin") {
        once(origin_line, "origin line", n);
        origin_line = n;
        grid.origin = v;
        have_origin = true;
      } else {
        if (deltas >= 3) throw InputError(name, n, "more than three delta lines");
        // The grid type is axis-aligned: delta k must point along axis k.
        for (int k = 0; k < 3; ++k)
          if (k != deltas && v[k] != 0.0)
            throw InputError(name, n,
                             "rotated or sheared grids are not supported (delta " +
                                 std::to_string(deltas + 1) + " must be along axis " +
                                 std::to_string(deltas + 1) + ")");
        if (!(v[deltas] > 0.0)) throw InputError(name, n, "grid spacing must be positive");
        grid.spacing[deltas] = v[deltas];
        ++deltas;
      }
    } else if (f[0] == "object" && f.size() >= 4 && f[3] == "array") {
      if (!have_counts) throw InputError(name, n, "data array before the gridpositions object");
      once(data_line, "data array", n);
      data_line = n;
      if (!have_origin || deltas != 3)
        throw InputError(name, n, "origin or delta lines missing before the data array");
      std::optional<long long> items;
      bool follows = false;
      for (std::size_t i = 4; i < f.size(); ++i) {
        if (f[i] == "items" && i + 1 < f.size()) items = parse_integer(f[i + 1]);
        if (f[i] == "follows") follows = true;
        if (f[i] == "type" && i + 1 < f.size() && f[i + 1] != "double" && f[i + 1] != "float")
          throw InputError(
              name, n,
              "unsupported data type '" + std::string(f[i + 1]) + "' (expected double or float)");
        if (f[i] == "rank" && i + 1 < f.size() && f[i + 1] != "0")
          throw InputError(name, n, "only scalar data (rank 0) is supported");
        if (f[i] == "binary" || f[i] == "msb" || f[i] == "lsb")
          throw InputError(name, n, "binary DX data is not supported (expected text data)");
      }
      expected = grid.size();
      if (!items || static_cast<std::size_t>(*items) != expected)
        throw InputError(name, n,
                         "items must equal nx*ny*nz = " + std::to_string(expected) +
                             " (counts on line " + std::to_string(counts_line) + ")");
      if (!follows)
        throw InputError(name, n,
                         "expected 'data follows' (external data files are not supported)");
      // Values are read in file order first, into no more memory than the text can hold
      // (2 bytes per value with its separator, the last one 1): a 229-byte file announcing
      // 1000^3 values used to zero 7.8 GB before reporting that it was short.
      std::vector<double> file_order;
      file_order.reserve(reservable(expected, 2, lines.remaining() + 1));
      const auto count_message = [&](const std::string& what) {
        return what + " " + std::to_string(file_order.size()) + " of " + std::to_string(expected) +
               " values (declared on line " + std::to_string(data_line) + ")";
      };
      std::string_view line;  // data lines: no comments inside the array
      while (file_order.size() < expected && lines.next(line)) {
        const auto fields = split_fields(line);
        // The objects after the data began before all values came: the header's counts
        // and the data disagree (said so, rather than "'attribute' is not a number").
        if (!fields.empty() &&
            (fields[0] == "attribute" || fields[0] == "object" || fields[0] == "component"))
          throw InputError(
              name, lines.line_number(),
              count_message("data ends after") + ", at '" + std::string(fields[0]) + "'");
        for (const auto field : fields) {
          const double value = require_double(field, "value", name, lines.line_number());
          if (file_order.size() >= expected)
            throw InputError(name, lines.line_number(),
                             "more values than the " + std::to_string(expected) +
                                 " items declared on line " + std::to_string(data_line));
          file_order.push_back(value);
        }
      }
      if (file_order.size() < expected)
        throw InputError(name, lines.line_number(), count_message("file ends after"));
      // File order has z fastest; the grid wants x fastest.
      grid.values.assign(expected, 0.0);
      const auto ny = static_cast<std::size_t>(grid.dims[1]);
      const auto nz = static_cast<std::size_t>(grid.dims[2]);
      for (std::size_t r = 0; r < expected; ++r)
        grid.at(static_cast<int>(r / (nz * ny)), static_cast<int>((r / nz) % ny),
                static_cast<int>(r % nz)) = file_order[r];
      have_data = true;
    }
    // gridconnections, attribute, field and component lines carry nothing we need.
  }
  if (!have_counts) throw InputError(name, "not an OpenDX grid: no 'class gridpositions' object");
  if (!have_data) throw InputError(name, "no 'class array ... data follows' object");
  return grid;
}

void write_dx(std::ostream& out, const Grid& grid) {
  const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  std::string text = "# Data written by molmesh (OpenDX scalar field, APBS layout)\n";
  auto vec = [&text](double a, double b, double c) {
    append_number(text, a);
    text += ' ';
    append_number(text, b);
    text += ' ';
    append_number(text, c);
    text += '\n';
  };
  const std::string counts =
      std::to_string(nx) + " " + std::to_string(ny) + " " + std::to_string(nz);
  text += "object 1 class gridpositions counts " + counts + "\norigin ";
  vec(grid.origin.x(), grid.origin.y(), grid.origin.z());
  text += "delta ";
  vec(grid.spacing.x(), 0.0, 0.0);
  text += "delta ";
  vec(0.0, grid.spacing.y(), 0.0);
  text += "delta ";
  vec(0.0, 0.0, grid.spacing.z());
  text += "object 2 class gridconnections counts " + counts + "\n";
  text += "object 3 class array type double rank 0 items " + std::to_string(grid.size()) +
          " data follows\n";
  // Three values per line in z-fastest order, as APBS writes them.
  int on_line = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j)
      for (int k = 0; k < nz; ++k) {
        append_number(text, grid.at(i, j, k));
        text += ++on_line == 3 ? '\n' : ' ';
        if (on_line == 3) on_line = 0;
        if (text.size() > (1 << 20)) {
          out << text;
          text.clear();
        }
      }
  if (on_line != 0) text.back() = '\n';
  text +=
      "attribute \"dep\" string \"positions\"\n"
      "object \"regular positions regular connections\" class field\n"
      "component \"positions\" value 1\n"
      "component \"connections\" value 2\n"
      "component \"data\" value 3\n";
  out << text;
}

}  // namespace molmesh
