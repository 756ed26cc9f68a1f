#include "molmesh/io/mcsf.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/geometry/predicates.hpp"
#include "molmesh/geometry/tetrahedron.hpp"
#include "molmesh/io/text_input.hpp"
#include "molmesh/io/text_output.hpp"

namespace molmesh {
namespace {

using FaceKey = std::array<int, 3>;

FaceKey sorted_key(int a, int b, int c) {
  FaceKey k{a, b, c};
  std::sort(k.begin(), k.end());
  return k;
}

struct FaceKeyHash {
  std::size_t operator()(const FaceKey& k) const {
    std::uint64_t h = static_cast<std::uint32_t>(k[0]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k[1]);
    h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint32_t>(k[2]);
    return static_cast<std::size_t>(h ^ (h >> 29));
  }
};

int type_of_marker(int marker, const McsfFaceTypes& types) {
  switch (marker) {
    case markers::kMolecularSurface:
      return types.molecular_surface;
    case markers::kOuterSphere:
      return types.outer_sphere;
    case markers::kActiveSite:
      return types.active_site;
    default:
      return types.other;
  }
}

int marker_of_type(int type, const McsfFaceTypes& types) {
  if (type == types.molecular_surface) return markers::kMolecularSurface;
  if (type == types.outer_sphere) return markers::kOuterSphere;
  if (type == types.active_site) return markers::kActiveSite;
  if (type == types.other) return markers::kNoMarker;
  return type + 100;
}

// Face types the reader did not recognise (marker_of_type: type + 100) outrank molmesh's own,
// so a user's boundary type is never hidden behind ours.
int marker_priority(int m) { return m >= 100 ? 4 : markers::vertex_marker_rank(m); }

// A tokenizer over the whole file that tracks line numbers and skips % comments.
class Lexer {
 public:
  Lexer(std::string text, std::string file) : text_(std::move(text)), file_(std::move(file)) {}

  // Next token: a run of [A-Za-z0-9_.+-] or a single punctuation character; empty at EOF.
  std::string_view next() {
    skip();
    if (pos_ >= text_.size()) return {};
    token_line_ = line_;
    const std::size_t start = pos_;
    if (is_word(text_[pos_])) {
      while (pos_ < text_.size() && is_word(text_[pos_])) ++pos_;
    } else {
      ++pos_;
    }
    return std::string_view(text_).substr(start, pos_ - start);
  }

  [[noreturn]] void fail(const std::string& msg) const {
    throw InputError(file_, token_line_, msg);
  }

  void expect(std::string_view want) {
    const auto t = next();
    if (t != want)
      fail("expected '" + std::string(want) + "' but found '" +
           (t.empty() ? std::string("end of file") : std::string(t)) + "'");
  }

  long long integer(const char* what) {
    const auto t = next();
    const auto v = io_detail::parse_integer(t);
    if (!v)
      fail(std::string("expected an integer (") + what + ") but found " +
           (t.empty() ? std::string("end of file") : io_detail::quoted(t)));
    return *v;
  }

  // An integer stored as int (markers, face types): larger magnitudes are refused, not
  // wrapped.
  int small_integer(const char* what) {
    const long long v = integer(what);
    if (v < -(1ll << 30) || v > (1ll << 30))
      fail(std::string(what) + " " + std::to_string(v) + " is out of range (|value| <= 2^30)");
    return static_cast<int>(v);
  }

  double real(const char* what) {
    const auto t = next();
    const auto v = io_detail::parse_double(t);
    if (!v)
      fail(std::string("expected a finite number (") + what + ") but found " +
           (t.empty() ? std::string("end of file") : io_detail::quoted(t)));
    return *v;
  }

  std::size_t size() const { return text_.size(); }

  std::size_t line() const { return token_line_; }

 private:
  static bool is_word(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '+' ||
           c == '-';
  }
  void skip() {
    while (pos_ < text_.size()) {
      const char c = text_[pos_];
      if (c == '\n') {
        ++line_;
        ++pos_;
      } else if (c == '%' || c == '#') {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        ++pos_;
      } else {
        return;
      }
    }
  }

  std::string text_;
  std::string file_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::size_t token_line_ = 1;
};

}  // namespace

void write_mcsf(const std::filesystem::path& path, const TetMesh& mesh,
                const McsfFaceTypes& types) {
  const std::size_t n_tets = mesh.tetrahedra.size();
  if (mesh.cell_markers.size() != n_tets && !mesh.cell_markers.empty())
    throw Error("write_mcsf: cell markers do not match the tetrahedra");
  if (mesh.boundary_face_markers.size() != mesh.boundary_faces.size())
    throw Error("write_mcsf: boundary face markers do not match the faces");

  // Which tet faces are shared (interior, type 0) and which marker the others carry. The
  // faces of all tets are sorted by their vertex triple, so a face is on the boundary
  // exactly when its key differs from both sorted neighbours (cheaper than a hash map of
  // four faces per tet, and linear in memory).
  struct TetFace {
    FaceKey key;
    std::uint32_t slot;  // 4 * tet + corner opposite the face
  };
  std::vector<TetFace> faces(n_tets * 4);
  for (std::size_t t = 0; t < n_tets; ++t) {
    const auto& tet = mesh.tetrahedra[t];
    for (int k = 0; k < 4; ++k)
      faces[4 * t + k] = {sorted_key(tet[kTetFaces[k][0]], tet[kTetFaces[k][1]], tet[kTetFaces[k][2]]),
                          static_cast<std::uint32_t>(4 * t + k)};
  }
  std::sort(faces.begin(), faces.end(),
            [](const TetFace& a, const TetFace& b) { return a.key < b.key; });
  std::unordered_map<FaceKey, int, FaceKeyHash> face_marker;
  face_marker.reserve(mesh.boundary_faces.size() * 2);
  for (std::size_t i = 0; i < mesh.boundary_faces.size(); ++i) {
    const auto& f = mesh.boundary_faces[i];
    face_marker[sorted_key(f[0], f[1], f[2])] = mesh.boundary_face_markers[i];
  }
  std::vector<int> face_type(n_tets * 4, 0);
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const bool shared = (i > 0 && faces[i - 1].key == faces[i].key) ||
                        (i + 1 < faces.size() && faces[i + 1].key == faces[i].key);
    if (shared) continue;
    const auto it = face_marker.find(faces[i].key);
    face_type[faces[i].slot] =
        type_of_marker(it == face_marker.end() ? markers::kNoMarker : it->second, types);
  }
  faces = {};

  write_file_atomically(path, [&](std::ostream& stream) {
    io_detail::TextOutput out(stream);
    out.text(
           "%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%\n"
           "% Written by molmesh. Material = region (1 molecule, 2 solvent). Face types:\n"
           "% 0 interior, ")
        .integer(types.molecular_surface)
        .text(" molecular surface, ")
        .integer(types.outer_sphere)
        .text(" outer sphere, ")
        .integer(types.active_site)
        .text(
            " active site (odd Dirichlet, even Neumann)\n"
            "%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%%\n\n"
            "mcsf_begin=1;\n\n"
            "      dim=3;         % intrinsic manifold dimension\n"
            "    dimii=3;         % imbedding manifold dimension\n"
            " vertices=")
        .integer(mesh.points.size())
        .text(";         % number of vertices\nsimplices=")
        .integer(n_tets)
        .text(
            ";         % number of simplices\n\n"
            "vert=[\n"
            "%-------- ---- ----------------- ----------------- -----------------\n"
            "% Vert-ID Chrt X-Coordinate      Y-Coordinate      Z-Coordinate\n"
            "%-------- ---- ----------------- ----------------- -----------------\n");
    for (std::size_t i = 0; i < mesh.points.size(); ++i) {
      out.integer(i).text(" 0");
      for (int d = 0; d < 3; ++d) out.ch(' ').scientific(mesh.points[i][d], 10);
      out.ch('\n');
    }
    out.text(
        "];\n\nsimp=[\n"
        "%-------- ---- ---- ------------------- ---------------------------------------\n"
        "% Simp-ID Grp  Mat  Face-Types          Vertex-Numbers\n"
        "%-------- ---- ---- ------------------- ---------------------------------------\n");
    for (std::size_t t = 0; t < n_tets; ++t) {
      Tetrahedron tet = mesh.tetrahedra[t];
      // Face types follow the corners: swapping corners 2 and 3 swaps faces 2 and 3.
      std::array<int, 4> type{face_type[4 * t], face_type[4 * t + 1], face_type[4 * t + 2],
                              face_type[4 * t + 3]};
      if (orient3d(mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]],
                   mesh.points[tet[3]]) < 0.0) {
        std::swap(tet[2], tet[3]);
        std::swap(type[2], type[3]);
      }
      out.integer(t).text(" 0 ").integer(mesh.cell_markers.empty() ? 0 : mesh.cell_markers[t]);
      for (int k = 0; k < 4; ++k) out.ch(' ').integer(type[k]);
      for (int v : tet) out.ch(' ').integer(v);
      out.ch('\n');
    }
    out.text("];\n\nmcsf_end=1;\n\n");
    out.finish();
  });
}

TetMesh read_mcsf(const std::filesystem::path& path, const McsfFaceTypes& types) {
  std::string text = io_detail::read_file_contents(path);
  io_detail::require_no_nul(text, path.string());
  Lexer lex(std::move(text), path.string());

  auto key_value = [&](std::string_view key) {
    lex.expect(key);
    lex.expect("=");
    const long long v = lex.integer(std::string(key).c_str());
    lex.expect(";");
    return v;
  };
  if (key_value("mcsf_begin") != 1) lex.fail("mcsf_begin must be 1");
  if (key_value("dim") != 3) lex.fail("only 3-dimensional meshes (dim=3) are supported");
  if (key_value("dimii") != 3) lex.fail("only meshes embedded in 3-D (dimii=3) are supported");
  const long long n_vertices = key_value("vertices");
  const long long n_simplices = key_value("simplices");
  if (n_vertices <= 0 || n_simplices <= 0 || n_vertices > (1ll << 31) || n_simplices > (1ll << 31))
    lex.fail("vertex and simplex counts must be positive");
  // Each vertex row has 5 fields and each simplex row 11, at least 2 bytes each: a header
  // announcing more than the file can hold is refused before memory is reserved for it.
  if (n_vertices * 10 + n_simplices * 22 > static_cast<long long>(lex.size()))
    lex.fail("the header announces " + std::to_string(n_vertices) + " vertices and " +
             std::to_string(n_simplices) + " simplices, more than the file's " +
             std::to_string(lex.size()) + " bytes can hold (truncated?)");

  TetMesh mesh;
  mesh.points.resize(static_cast<std::size_t>(n_vertices));
  lex.expect("vert");
  lex.expect("=");
  lex.expect("[");
  for (long long i = 0; i < n_vertices; ++i) {
    if (lex.integer("vertex id") != i) lex.fail("vertex ids must be 0, 1, 2, ... in order");
    lex.integer("chart");
    for (int d = 0; d < 3; ++d) mesh.points[i][d] = lex.real("coordinate");
  }
  lex.expect("]");
  lex.expect(";");

  lex.expect("simp");
  lex.expect("=");
  lex.expect("[");
  mesh.tetrahedra.resize(static_cast<std::size_t>(n_simplices));
  mesh.cell_markers.resize(static_cast<std::size_t>(n_simplices));
  std::vector<std::array<int, 4>> face_types(static_cast<std::size_t>(n_simplices));
  for (long long t = 0; t < n_simplices; ++t) {
    if (lex.integer("simplex id") != t) lex.fail("simplex ids must be 0, 1, 2, ... in order");
    lex.integer("group");
    mesh.cell_markers[t] = lex.small_integer("material");
    for (int k = 0; k < 4; ++k) face_types[t][k] = lex.small_integer("face type");
    for (int k = 0; k < 4; ++k) {
      const long long v = lex.integer("vertex number");
      if (v < 0 || v >= n_vertices)
        lex.fail("vertex number " + std::to_string(v) + " out of range [0, " +
                 std::to_string(n_vertices) + ")");
      mesh.tetrahedra[t][k] = static_cast<int>(v);
    }
    const auto& tet = mesh.tetrahedra[t];
    const double det = orient3d(mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]],
                                mesh.points[tet[3]]);
    if (det == 0.0) lex.fail("simplex " + std::to_string(t) + " is flat (zero volume)");
    if (det < 0.0) {
      std::swap(mesh.tetrahedra[t][2], mesh.tetrahedra[t][3]);
      std::swap(face_types[t][2], face_types[t][3]);
    }
  }
  lex.expect("]");
  lex.expect(";");
  if (key_value("mcsf_end") != 1) lex.fail("mcsf_end must be 1");

  mesh.vertex_markers.assign(mesh.points.size(), markers::kNoMarker);
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& tet = mesh.tetrahedra[t];
    for (int k = 0; k < 4; ++k) {
      if (face_types[t][k] == 0) continue;
      const Triangle f{tet[kTetFaces[k][0]], tet[kTetFaces[k][1]], tet[kTetFaces[k][2]]};
      const int m = marker_of_type(face_types[t][k], types);
      mesh.boundary_faces.push_back(f);
      mesh.boundary_face_markers.push_back(m);
      for (int v : f)
        if (marker_priority(m) > marker_priority(mesh.vertex_markers[v]))
          mesh.vertex_markers[v] = m;
    }
  }
  return mesh;
}

}  // namespace molmesh
