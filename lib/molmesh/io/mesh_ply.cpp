#include "molmesh/io/mesh_ply.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/text_input.hpp"

namespace molmesh {
namespace {

using namespace io_detail;

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

std::optional<Type> type_from_name(std::string_view s) {
  if (s == "char" || s == "int8") return Type::Int8;
  if (s == "uchar" || s == "uint8") return Type::UInt8;
  if (s == "short" || s == "int16") return Type::Int16;
  if (s == "ushort" || s == "uint16") return Type::UInt16;
  if (s == "int" || s == "int32") return Type::Int32;
  if (s == "uint" || s == "uint32") return Type::UInt32;
  if (s == "float" || s == "float32") return Type::Float32;
  if (s == "double" || s == "float64") return Type::Float64;
  return std::nullopt;
}

std::size_t type_size(Type t) {
  switch (t) {
    case Type::Int8:
    case Type::UInt8:
      return 1;
    case Type::Int16:
    case Type::UInt16:
      return 2;
    case Type::Int32:
    case Type::UInt32:
    case Type::Float32:
      return 4;
    case Type::Float64:
      return 8;
  }
  return 0;
}

struct Property {
  std::string name;
  Type type = Type::Float32;
  bool list = false;
  Type count_type = Type::UInt8;
};

struct Element {
  std::string name;
  std::size_t count = 0;
  std::vector<Property> properties;
  std::size_t header_line = 0;
};

enum class Encoding { Ascii, Little, Big };

// Reads values one after another from the body, in either encoding, tracking the line
// (ascii) or the byte offset (binary) for messages.
class BodyReader {
 public:
  BodyReader(const std::string& bytes, std::size_t start, std::size_t first_line, Encoding encoding,
             const std::string& name)
      : bytes_(bytes), pos_(start), line_(first_line), encoding_(encoding), name_(name) {}

  double read(Type t) {
    if (encoding_ == Encoding::Ascii) return read_ascii();
    const std::size_t n = type_size(t);
    if (pos_ + n > bytes_.size())
      throw InputError(
          name_, "binary data ends early at byte " + std::to_string(pos_) + " (file truncated?)");
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + pos_, n);
    pos_ += n;
    const bool swap = (encoding_ == Encoding::Big) == (std::endian::native == std::endian::little);
    if (swap)
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(raw[i], raw[n - 1 - i]);
    switch (t) {
      case Type::Int8:
        return static_cast<double>(static_cast<std::int8_t>(raw[0]));
      case Type::UInt8:
        return static_cast<double>(raw[0]);
      case Type::Int16:
        return load<std::int16_t>(raw);
      case Type::UInt16:
        return load<std::uint16_t>(raw);
      case Type::Int32:
        return load<std::int32_t>(raw);
      case Type::UInt32:
        return load<std::uint32_t>(raw);
      case Type::Float32:
        return load<float>(raw);
      case Type::Float64:
        return load<double>(raw);
    }
    return 0.0;
  }

  // Ascii files hold one element per line: called after each element.
  void end_element() {
    if (encoding_ != Encoding::Ascii) return;
    skip_blanks();
    if (pos_ < bytes_.size() && bytes_[pos_] != '\n' && bytes_[pos_] != '\r')
      throw InputError(name_, line_, "more values than the header declares for this element");
    while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
    if (pos_ < bytes_.size()) ++pos_;
    ++line_;
  }

  std::size_t line() const { return encoding_ == Encoding::Ascii ? line_ : 0; }
  std::size_t remaining() const { return pos_ < bytes_.size() ? bytes_.size() - pos_ : 0; }
  // The fewest bytes one item of `e` can take: its scalars and list counts (lists may be
  // empty); an ascii value takes at least 2 bytes with its separator.
  std::size_t min_item_bytes(const Element& e) const {
    std::size_t bytes = 0;
    for (const Property& p : e.properties)
      bytes += encoding_ == Encoding::Ascii ? 2 : type_size(p.list ? p.count_type : p.type);
    return bytes;
  }
  std::string where() const {
    return encoding_ == Encoding::Ascii ? "" : " (byte " + std::to_string(pos_) + ")";
  }

 private:
  template <class T>
  static double load(const unsigned char* raw) {
    T value;
    std::memcpy(&value, raw, sizeof value);
    return static_cast<double>(value);
  }

  void skip_blanks() {
    while (pos_ < bytes_.size() && (bytes_[pos_] == ' ' || bytes_[pos_] == '\t')) ++pos_;
  }

  double read_ascii() {
    skip_blanks();
    // Blank lines between elements are tolerated.
    while (pos_ < bytes_.size() && (bytes_[pos_] == '\n' || bytes_[pos_] == '\r')) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
      skip_blanks();
    }
    if (pos_ >= bytes_.size())
      throw InputError(name_, line_, "file ends before all elements are read");
    std::size_t end = pos_;
    while (end < bytes_.size() && bytes_[end] != ' ' && bytes_[end] != '\t' &&
           bytes_[end] != '\n' && bytes_[end] != '\r')
      ++end;
    const std::string_view field(bytes_.data() + pos_, end - pos_);
    const double value = require_double(field, "value", name_, line_);
    pos_ = end;
    return value;
  }

  const std::string& bytes_;
  std::size_t pos_;
  std::size_t line_;
  Encoding encoding_;
  const std::string& name_;
};

}  // namespace

SurfaceMesh parse_ply(const std::string& bytes, const std::string& name) {
  LineCursor lines(bytes);
  std::string_view line;
  if (!lines.next(line) || trim(line) != "ply")
    throw InputError(name, 1, "not a PLY file: the first line must be 'ply'");
  std::optional<Encoding> encoding;
  std::vector<Element> elements;
  std::size_t header_end = 0;  // byte offset of the body
  std::size_t offset = bytes.find('\n') + 1;
  bool ended = false;
  while (lines.next(line)) {
    // The header is always '\n'-terminated lines; track the byte offset ourselves.
    const std::size_t line_start = offset;
    offset = bytes.find('\n', line_start);
    offset = offset == std::string::npos ? bytes.size() : offset + 1;
    const std::size_t n = lines.line_number();
    const auto f = split_fields(line);
    if (f.empty() || f[0] == "comment" || f[0] == "obj_info") continue;
    if (f[0] == "end_header") {
      header_end = offset;
      ended = true;
      break;
    }
    if (f[0] == "format") {
      if (f.size() < 2) throw InputError(name, n, "format line needs an encoding");
      if (f[1] == "ascii")
        encoding = Encoding::Ascii;
      else if (f[1] == "binary_little_endian")
        encoding = Encoding::Little;
      else if (f[1] == "binary_big_endian")
        encoding = Encoding::Big;
      else
        throw InputError(name, n, "unknown PLY encoding '" + std::string(f[1]) + "'");
    } else if (f[0] == "element") {
      const auto count = f.size() == 3 ? parse_integer(f[2]) : std::nullopt;
      if (!count || *count < 0) throw InputError(name, n, "expected 'element NAME COUNT'");
      // One vertex and one face element: the points of two would share one index space
      // and their marker arrays would not line up with the points (or faces).
      if (f[1] == "vertex" || f[1] == "face")
        for (const Element& e : elements)
          if (e.name == f[1])
            throw InputError(name, n,
                             "a second '" + e.name + "' element (the first is on line " +
                                 std::to_string(e.header_line) + ")");
      elements.push_back({std::string(f[1]), static_cast<std::size_t>(*count), {}, n});
    } else if (f[0] == "property") {
      if (elements.empty()) throw InputError(name, n, "property before any element");
      Property p;
      if (f.size() == 5 && f[1] == "list") {
        const auto ct = type_from_name(f[2]);
        const auto vt = type_from_name(f[3]);
        if (!ct || !vt) throw InputError(name, n, "unknown property type in list");
        p = {std::string(f[4]), *vt, true, *ct};
      } else if (f.size() == 3) {
        const auto t = type_from_name(f[1]);
        if (!t) throw InputError(name, n, "unknown property type '" + std::string(f[1]) + "'");
        p = {std::string(f[2]), *t, false, Type::UInt8};
      } else {
        throw InputError(name, n,
                         "expected 'property TYPE NAME' or 'property list TYPE TYPE NAME'");
      }
      elements.back().properties.push_back(p);
    } else {
      throw InputError(name, n, "unknown header keyword '" + std::string(f[0]) + "'");
    }
  }
  if (!ended) throw InputError(name, "PLY header has no end_header line");
  if (!encoding) throw InputError(name, "PLY header has no format line");

  SurfaceMesh mesh;
  std::size_t vertex_count = 0;
  bool seen_vertices = false;
  BodyReader body(bytes, header_end, lines.line_number() + 1, *encoding, name);
  // Indices and markers are integers that fit an int; a float of 1e30 or NaN is refused
  // (converting it would be undefined behaviour).
  auto integral = [&](double v, const char* what, std::size_t item_line) -> long long {
    if (!(std::abs(v) < 2147483648.0) || v != std::floor(v))
      throw InputError(
          name, item_line,
          std::string(what) + " " + std::to_string(v) + " is not an integer" + body.where());
    return static_cast<long long>(v);
  };
  std::vector<long long> corners;
  for (const Element& e : elements) {
    const bool is_vertex = e.name == "vertex";
    const bool is_face = e.name == "face";
    int xyz[3] = {-1, -1, -1};
    int marker = -1;
    int indices = -1;
    for (std::size_t i = 0; i < e.properties.size(); ++i) {
      const auto& p = e.properties[i];
      const int k = static_cast<int>(i);
      if (is_vertex && !p.list && p.name == "x") xyz[0] = k;
      if (is_vertex && !p.list && p.name == "y") xyz[1] = k;
      if (is_vertex && !p.list && p.name == "z") xyz[2] = k;
      if ((is_vertex || is_face) && !p.list && p.name == "marker") marker = k;
      if (is_face && p.list && (p.name == "vertex_indices" || p.name == "vertex_index"))
        indices = k;
    }
    if (is_vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
      throw InputError(name, e.header_line, "vertex element lacks x, y or z");
    if (is_face && indices < 0)
      throw InputError(name, e.header_line, "face element lacks a vertex_indices list");
    if (is_face && !seen_vertices)
      throw InputError(name, e.header_line, "face element before the vertex element");
    if (e.count > 0 && e.properties.empty())
      throw InputError(
          name, e.header_line,
          "element '" + e.name + "' has " + std::to_string(e.count) + " items but no properties");
    if (is_vertex) {
      // Never more than the body can hold (the last ascii value may lack a separator); a
      // short body is reported where it ends.
      const std::size_t n = reservable(e.count, body.min_item_bytes(e), body.remaining() + 1);
      mesh.points.reserve(n);
      if (marker >= 0) mesh.vertex_markers.reserve(n);
    }
    for (std::size_t item = 0; item < e.count; ++item) {
      const std::size_t item_line = body.line();
      Vec3 p = Vec3::Zero();
      int mark = 0;
      corners.clear();
      for (std::size_t i = 0; i < e.properties.size(); ++i) {
        const Property& prop = e.properties[i];
        const int k = static_cast<int>(i);
        if (prop.list) {
          const double count = body.read(prop.count_type);
          // Negated so that NaN (a float count type) is refused too.
          if (!(count >= 0 && count <= 1e6) || count != std::floor(count))
            throw InputError(name, item_line,
                             "invalid list length " + std::to_string(count) + body.where());
          for (long long c = 0; c < static_cast<long long>(count); ++c) {
            const double v = body.read(prop.type);
            if (k == indices) corners.push_back(integral(v, "vertex index", item_line));
          }
        } else {
          const double v = body.read(prop.type);
          if (is_vertex && k == xyz[0]) p.x() = v;
          if (is_vertex && k == xyz[1]) p.y() = v;
          if (is_vertex && k == xyz[2]) p.z() = v;
          if (k == marker) mark = static_cast<int>(integral(v, "marker", item_line));
        }
      }
      if (is_vertex) {
        if (!p.allFinite())
          throw InputError(
              name, item_line,
              "vertex " + std::to_string(item) + " has non-finite coordinates" + body.where());
        mesh.points.push_back(p);
        if (marker >= 0) mesh.vertex_markers.push_back(mark);
      } else if (is_face) {
        const std::size_t before = mesh.triangles.size();
        try {
          append_polygon(corners, vertex_count, mesh.triangles, name, item_line);
        } catch (const InputError& error) {
          if (item_line != 0) throw;
          throw InputError(name, std::string(error.what()).substr(name.size() + 2) + " in face " +
                                     std::to_string(item));
        }
        if (marker >= 0)
          mesh.face_markers.insert(mesh.face_markers.end(), mesh.triangles.size() - before, mark);
      }
      body.end_element();
    }
    if (is_vertex) {
      vertex_count = mesh.points.size();
      seen_vertices = true;
    }
  }
  if (!seen_vertices) throw InputError(name, "PLY file has no vertex element");
  return mesh;
}

void write_ply(std::ostream& out, const SurfaceMesh& mesh) {
  static_assert(std::endian::native == std::endian::little, "writer assumes a little-endian host");
  const bool vmark =
      !mesh.vertex_markers.empty() && mesh.vertex_markers.size() == mesh.points.size();
  const bool fmark =
      !mesh.face_markers.empty() && mesh.face_markers.size() == mesh.triangles.size();
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by molmesh\n";
  header += "element vertex " + std::to_string(mesh.points.size()) + "\n";
  header += "property double x\nproperty double y\nproperty double z\n";
  if (vmark) header += "property int marker\n";
  header += "element face " + std::to_string(mesh.triangles.size()) + "\n";
  header += "property list uchar int vertex_indices\n";
  if (fmark) header += "property int marker\n";
  header += "end_header\n";
  out << header;
  std::string body;
  auto put = [&body](const auto& value) {
    const char* raw = reinterpret_cast<const char*>(&value);
    body.append(raw, sizeof value);
  };
  auto flush = [&] {
    if (body.size() > (1 << 20)) {
      out.write(body.data(), static_cast<std::streamsize>(body.size()));
      body.clear();
    }
  };
  for (std::size_t i = 0; i < mesh.points.size(); ++i) {
    put(mesh.points[i].x());
    put(mesh.points[i].y());
    put(mesh.points[i].z());
    if (vmark) put(static_cast<std::int32_t>(mesh.vertex_markers[i]));
    flush();
  }
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    put(static_cast<std::uint8_t>(3));
    for (int v : mesh.triangles[i]) put(static_cast<std::int32_t>(v));
    if (fmark) put(static_cast<std::int32_t>(mesh.face_markers[i]));
    flush();
  }
  out.write(body.data(), static_cast<std::streamsize>(body.size()));
}

}  // namespace molmesh
