#include "molmesh/io/mcsf.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
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

// Calls visit(slot, smallest vertex, other two as one word) for the four faces of tet t,
// from one sort of its corners: the face opposite corner k is the sorted corners without k
// (kTetFaces[k] as a set), so each face costs no sort of its own.
template <class Visit>
void for_each_face(const Tetrahedron& tet, std::size_t t, Visit&& visit) {
  std::array<std::uint64_t, 4> s{};  // vertex << 2 | corner
  for (int k = 0; k < 4; ++k)
    s[k] = (std::uint64_t{static_cast<std::uint32_t>(tet[k])} << 2) | static_cast<unsigned>(k);
  const auto order = [&s](int i, int j) {
    if (s[j] < s[i]) std::swap(s[i], s[j]);
  };
  order(0, 1);
  order(2, 3);
  order(0, 2);
  order(1, 3);
  order(1, 2);
  const auto v = [&s](int p) { return static_cast<std::uint32_t>(s[p] >> 2); };
  const auto pair = [](std::uint32_t a, std::uint32_t b) { return std::uint64_t{a} << 32 | b; };
  const auto slot = [&](int p) { return static_cast<std::uint32_t>(4 * t + (s[p] & 3)); };
  visit(slot(0), v(1), pair(v(2), v(3)));
  visit(slot(1), v(0), pair(v(2), v(3)));
  visit(slot(2), v(0), pair(v(1), v(3)));
  visit(slot(3), v(0), pair(v(1), v(2)));
}

// The MCSF type of each tet face, at slot 4 * tet + corner opposite the face: 0 where
// another tet shares the face, else the type of the boundary marker the face carries
// (types.other without one). A face is shared when its sorted vertex triple occurs twice.
// Sorting all 4T triples with std::sort was 40 % of the writer's time on mAChE's 675k tets
// (issue 14), and scattering them straight into one bucket per smallest vertex cost nearly
// as much (a cache miss per face). So the faces are counting-sorted by their smallest
// vertex in two passes: into at most 1024 buckets by its top bits (few enough write streams
// to stay in cache), then, bucket by bucket in parallel, by the vertex itself; a vertex's
// faces, about 25, are then sorted by the other two. Each slot's type depends only on the
// mesh, never on the thread count or the order the chunks run in.
std::vector<int> tet_face_types(const TetMesh& mesh, const McsfFaceTypes& types) {
  const std::size_t n_points = mesh.points.size();
  const std::size_t n_tets = mesh.tetrahedra.size();
  const std::size_t n_faces = 4 * n_tets;
  if (n_faces > std::numeric_limits<std::uint32_t>::max())
    throw Error("write_mcsf: more tetrahedra than the face table can index");
  for (const auto& tet : mesh.tetrahedra)
    for (const int v : tet)
      if (v < 0 || static_cast<std::size_t>(v) >= n_points)
        throw Error("write_mcsf: a tetrahedron's vertex " + std::to_string(v) +
                    " is not one of the " + std::to_string(n_points) + " points");
  const auto face_of = [&](std::size_t slot) {
    const auto& tet = mesh.tetrahedra[slot / 4];
    const auto& corners = kTetFaces[slot % 4];
    return sorted_key(tet[corners[0]], tet[corners[1]], tet[corners[2]]);
  };
  struct Entry {
    std::uint32_t first;  // smallest vertex
    std::uint32_t slot;
    std::uint64_t rest;  // the other two, so faces compare as two integers
  };
  const int shift = std::max(0, static_cast<int>(std::bit_width(n_points)) - 10);
  const std::size_t n_buckets = (n_points >> shift) + 1;
  // Fixed chunks of tets, each with its own counts, so where an entry lands does not
  // depend on the threads.
  constexpr std::size_t kChunk = 8192;
  const std::size_t n_chunks = (n_tets + kChunk - 1) / kChunk;
  const auto for_each_face_of_chunk = [&](std::size_t c, auto&& visit) {
    for (std::size_t t = c * kChunk; t < std::min(n_tets, (c + 1) * kChunk); ++t)
      for_each_face(mesh.tetrahedra[t], t, visit);
  };
  std::vector<std::uint32_t> next(n_chunks * n_buckets, 0);
  tbb::parallel_for(std::size_t{0}, n_chunks, [&](std::size_t c) {
    std::uint32_t* const counts = next.data() + c * n_buckets;
    for_each_face_of_chunk(
        c, [&](std::uint32_t, std::uint32_t first, std::uint64_t) { ++counts[first >> shift]; });
  });
  // Bucket b holds chunk 0's faces of b, then chunk 1's, ...
  std::vector<std::uint32_t> bucket_begin(n_buckets + 1);
  std::uint32_t sum = 0;
  for (std::size_t b = 0; b < n_buckets; ++b) {
    bucket_begin[b] = sum;
    for (std::size_t c = 0; c < n_chunks; ++c) sum += std::exchange(next[c * n_buckets + b], sum);
  }
  bucket_begin[n_buckets] = sum;
  std::vector<Entry> entries(n_faces);
  tbb::parallel_for(std::size_t{0}, n_chunks, [&](std::size_t c) {
    std::uint32_t* const to = next.data() + c * n_buckets;
    for_each_face_of_chunk(c, [&](std::uint32_t slot, std::uint32_t first, std::uint64_t rest) {
      entries[to[first >> shift]++] = {first, slot, rest};
    });
  });
  std::unordered_map<FaceKey, int, FaceKeyHash> face_marker;
  face_marker.reserve(mesh.boundary_faces.size() * 2);
  for (std::size_t i = 0; i < mesh.boundary_faces.size(); ++i) {
    const auto& f = mesh.boundary_faces[i];
    face_marker[sorted_key(f[0], f[1], f[2])] = mesh.boundary_face_markers[i];
  }
  std::vector<int> face_type(n_faces, 0);
  // Within a bucket, a counting sort by the smallest vertex (in cache), then each vertex's
  // faces, about 25, sorted by the other two.
  tbb::parallel_for(std::size_t{0}, n_buckets, [&](std::size_t b) {
    const std::uint32_t low = static_cast<std::uint32_t>(b) << shift;
    std::vector<std::uint32_t> begin((std::size_t{1} << shift) + 1, 0);
    for (std::uint32_t i = bucket_begin[b]; i < bucket_begin[b + 1]; ++i)
      ++begin[entries[i].first - low + 1];
    for (std::size_t v = 1; v < begin.size(); ++v) begin[v] += begin[v - 1];
    std::vector<Entry> by_vertex(bucket_begin[b + 1] - bucket_begin[b]);
    {
      std::vector<std::uint32_t> to(begin.begin(), begin.end() - 1);
      for (std::uint32_t i = bucket_begin[b]; i < bucket_begin[b + 1]; ++i)
        by_vertex[to[entries[i].first - low]++] = entries[i];
    }
    for (std::size_t v = 0; v + 1 < begin.size(); ++v) {
      Entry* const first = by_vertex.data() + begin[v];
      Entry* const last = by_vertex.data() + begin[v + 1];
      std::sort(first, last, [](const Entry& x, const Entry& y) { return x.rest < y.rest; });
      for (Entry* e = first; e != last; ++e) {
        if ((e != first && e[-1].rest == e->rest) || (e + 1 != last && e[1].rest == e->rest))
          continue;
        const auto it = face_marker.find(face_of(e->slot));
        face_type[e->slot] =
            type_of_marker(it == face_marker.end() ? markers::kNoMarker : it->second, types);
      }
    }
  });
  return face_type;
}

}  // namespace

void write_mcsf(const std::filesystem::path& path, const TetMesh& mesh,
                const McsfFaceTypes& types) {
  const std::size_t n_tets = mesh.tetrahedra.size();
  if (mesh.cell_markers.size() != n_tets && !mesh.cell_markers.empty())
    throw Error("write_mcsf: cell markers do not match the tetrahedra");
  if (mesh.boundary_face_markers.size() != mesh.boundary_faces.size())
    throw Error("write_mcsf: boundary face markers do not match the faces");

  const std::vector<int> face_type = tet_face_types(mesh, types);
  // Tets are written positively oriented (FETK's convention); computed ahead, in parallel,
  // as the orientation reads the points in tet order, which is mostly cache misses.
  std::vector<char> flip(n_tets);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n_tets, 4096), [&](const auto& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      const Tetrahedron& tet = mesh.tetrahedra[t];
      flip[t] = orient3d(mesh.points[tet[0]], mesh.points[tet[1]], mesh.points[tet[2]],
                         mesh.points[tet[3]]) < 0.0;
    }
  });

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
      if (flip[t]) {
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
