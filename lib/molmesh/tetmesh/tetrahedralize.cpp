#include "molmesh/tetmesh/tetrahedralize.hpp"

#include <tetgen.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "molmesh/core/error.hpp"
#include "molmesh/core/timing.hpp"
#include "molmesh/geometry/predicates.hpp"
#include "molmesh/geometry/tetrahedron.hpp"
#include "molmesh/geometry/winding_number.hpp"
#include "molmesh/processing/self_intersection.hpp"
#include "molmesh/tetmesh/markers.hpp"
#include "molmesh/tetmesh/molecule_size.hpp"
#include "molmesh/tetmesh/outer_sphere.hpp"
#include "molmesh/tetmesh/size_field.hpp"
#include "molmesh/tetmesh/tetgen_output.hpp"
#include "molmesh/tetmesh/tetgen_plc.hpp"

namespace molmesh {
namespace detail {
void link_tetgen_terminate_override();  // tetgen_terminate.cpp
}
namespace {

// What a tetrahedron costs in TetGen's pools, its output arrays and our TetMesh (measured
// order of magnitude, generous), for the memory estimate below.
constexpr double kBytesPerTetrahedron = 400.0;
// Hole points at most (atom centres inside the molecule) for exterior meshes.
constexpr std::size_t kMaxHolePoints = 16;

using Clock = std::chrono::steady_clock;

struct PointKeyHash {
  std::size_t operator()(const std::array<std::uint64_t, 3>& k) const {
    std::uint64_t h = k[0];
    h = h * 0x9E3779B97F4A7C15ull ^ k[1];
    h = h * 0x9E3779B97F4A7C15ull ^ k[2];
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};
// Exact bit pattern: TetGen copies input coordinates unchanged, so an atom centre that
// became a node is found by equality.
std::array<std::uint64_t, 3> point_key(const Vec3& p) {
  return {std::bit_cast<std::uint64_t>(p.x() + 0.0), std::bit_cast<std::uint64_t>(p.y() + 0.0),
          std::bit_cast<std::uint64_t>(p.z() + 0.0)};
}

std::string tetgen_error_message(int code) {
  switch (code) {
    case 1:
      return "TetGen ran out of memory";
    case 2:
      return "TetGen hit an internal error";
    case 3:
      return "the surface intersects itself (TetGen found self-intersecting facets); run the "
             "surface quality improvement, or check the input surface";
    case 4:
      return "the surface has a feature much smaller than the mesh (TetGen: very small input "
             "feature size); improve or coarsen the surface";
    case 5:
      return "two surface facets are nearly coplanar and overlapping (TetGen); improve the "
             "surface";
    case 10:
      return "TetGen rejected the input (an invalid facet or point)";
    default:
      return "TetGen failed with code " + std::to_string(code);
  }
}

std::string format_number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string format_point(const Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.6g, %.6g, %.6g)", p.x(), p.y(), p.z());
  return buf;
}

// TetGen's input must be a valid PLC: TetGen 1.5 detects some defects (self-intersections)
// only deep inside its run, others (near-duplicate vertices, a non-manifold edge) it may
// mesh wrongly or crash on. So the surface is checked here, with messages that name the
// defect and where it is. Order: cheap combinatorial checks first.
void validate_plc(const SurfaceMesh& s) {
  const int n = static_cast<int>(s.points.size());
  for (std::size_t v = 0; v < s.points.size(); ++v)
    if (!s.points[v].allFinite())
      throw Error("surface vertex " + std::to_string(v) + " has a non-finite coordinate");
  // Directed edge (a -> b) uses: a closed, manifold, consistently oriented surface has each
  // directed edge exactly once and its reverse exactly once.
  std::unordered_map<std::uint64_t, int> directed;
  directed.reserve(s.triangles.size() * 4);
  auto key = [](int a, int b) {
    return static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32 |
           static_cast<std::uint32_t>(b);
  };
  for (const auto& t : s.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a < 0 || a >= n)
        throw Error("surface triangle refers to vertex " + std::to_string(a) + " of " +
                    std::to_string(n));
      if (a == b) throw Error("surface has a degenerate triangle (repeated vertex)");
      ++directed[key(a, b)];
    }
  }
  std::size_t open = 0, non_manifold = 0, misoriented = 0;
  Vec3 example = Vec3::Zero();
  bool have_example = false;
  for (const auto& [edge, count] : directed) {
    const int a = static_cast<int>(edge >> 32), b = static_cast<int>(edge & 0xffffffffu);
    const auto reverse = directed.find(key(b, a));
    const int back = reverse == directed.end() ? 0 : reverse->second;
    const bool bad = count > 1 || back == 0 || back > 1;
    if (count > 1 && back > 0)
      ++non_manifold;
    else if (count > 1)
      ++misoriented;
    else if (back == 0)
      ++open;
    else if (back > 1)
      ++non_manifold;
    if (bad && !have_example) {
      example = (s.points[a] + s.points[b]) / 2.0;
      have_example = true;
    }
  }
  if (open > 0)
    throw Error("the molecular surface is not closed (" + std::to_string(open) +
                " edges with a single triangle, e.g. at " + format_point(example) +
                "); a tetrahedral mesh needs a watertight surface");
  if (non_manifold > 0 || misoriented > 0)
    throw Error("the molecular surface is not a manifold consistently oriented surface (" +
                std::to_string(non_manifold + misoriented) +
                " edges shared by more than two triangles or used twice in one direction, "
                "e.g. at " +
                format_point(example) + "); repair it (molmesh improve) before meshing");

  // Near-duplicate vertices: TetGen merges or rejects points closer than its tolerance
  // (relative to the bounding box), which breaks facets that use both.
  Vec3 lo = s.points.front(), hi = s.points.front();
  for (const auto& p : s.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double tolerance = 1e-9 * (hi - lo).norm();
  if (tolerance > 0.0) {
    // Hash grid of cell size `tolerance`: a close pair lies in neighbouring cells. Cell
    // coordinates stay below ~1e9 since the tolerance is 1e-9 of the box diagonal.
    using Cell = std::array<std::int64_t, 3>;
    struct CellHash {
      std::size_t operator()(const Cell& c) const {
        std::uint64_t h = static_cast<std::uint64_t>(c[0]);
        h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(c[1]);
        h = h * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(c[2]);
        return static_cast<std::size_t>(h ^ (h >> 31));
      }
    };
    std::unordered_map<Cell, std::vector<int>, CellHash> cells;
    cells.reserve(s.points.size());
    auto cell_of = [&](const Vec3& p) {
      const Vec3 c = (p - lo) / tolerance;
      return Cell{static_cast<std::int64_t>(c.x()), static_cast<std::int64_t>(c.y()),
                  static_cast<std::int64_t>(c.z())};
    };
    for (int i = 0; i < n; ++i) {
      const Vec3& p = s.points[static_cast<std::size_t>(i)];
      const Cell c = cell_of(p);
      for (int dz = -1; dz <= 1; ++dz)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dx = -1; dx <= 1; ++dx) {
            const auto it = cells.find({c[0] + dx, c[1] + dy, c[2] + dz});
            if (it == cells.end()) continue;
            for (int j : it->second)
              if ((s.points[static_cast<std::size_t>(j)] - p).norm() <= tolerance)
                throw Error("surface vertices " + std::to_string(j) + " and " + std::to_string(i) +
                            " coincide (closer than " + format_number(tolerance) + " Å) at " +
                            format_point(p) + "; merge them (molmesh improve) before meshing");
          }
      cells[c].push_back(i);
    }
  }

  const auto crossings = self_intersections(s);
  if (!crossings.empty()) {
    const Triangle& t = s.triangles[static_cast<std::size_t>(crossings.front().first)];
    throw Error("the molecular surface intersects itself (" + std::to_string(crossings.size()) +
                " crossing triangle pairs, e.g. near " +
                format_point((s.points[t[0]] + s.points[t[1]] + s.points[t[2]]) / 3.0) +
                "); TetGen needs a surface that bounds a solid");
  }
}

// Mean length of the edges at each vertex: the local mesh size the surface already has.
std::vector<double> mean_edge_lengths(const SurfaceMesh& s) {
  std::vector<double> sum(s.points.size(), 0.0);
  std::vector<int> count(s.points.size(), 0);
  for (const auto& t : s.triangles)
    for (int k = 0; k < 3; ++k) {
      // Each interior edge is seen from both triangles, so both ends get it twice.
      const int a = t[k], b = t[(k + 1) % 3];
      const double length = (s.points[a] - s.points[b]).norm();
      sum[a] += length;
      sum[b] += length;
      count[a] += 1;
      count[b] += 1;
    }
  for (std::size_t i = 0; i < sum.size(); ++i) sum[i] = count[i] ? sum[i] / count[i] : 0.0;
  return sum;
}

// TetGen's background mesh for -m: the Delaunay tetrahedralisation of the points that carry
// the size field, with their sizes. TetGen interpolates it linearly at every vertex it
// inserts (instead of within its current, long tetrahedra between the surface and the
// outer sphere, which grades sizes linearly in the distance).
void background_mesh(const std::vector<Vec3>& points, const std::vector<double>& sizes,
                     tetgenio& bg) {
  tetgenio in;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(points.size());
  in.pointlist = new REAL[points.size() * 3];
  for (std::size_t i = 0; i < points.size(); ++i)
    for (int d = 0; d < 3; ++d) in.pointlist[3 * i + d] = points[i][d];
  tetgenbehavior behavior;
  char switches[] = "zQ";
  if (!behavior.parse_commandline(switches)) throw Error("TetGen rejected the switches \"zQ\"");
  tetgenio out;
  try {
    ::tetrahedralize(&behavior, &in, &out, nullptr, nullptr);
  } catch (int code) {
    throw Error("the size field's background mesh failed: " + tetgen_error_message(code));
  }
  if (out.numberofpoints != in.numberofpoints || out.numberoftetrahedra <= 0)
    throw Error("the size field's background mesh lost points (TetGen)");
  if (!std::equal(in.pointlist, in.pointlist + 3 * in.numberofpoints, out.pointlist))
    throw Error("the size field's background mesh reordered its points (TetGen)");
  bg.firstnumber = 0;
  bg.numberofpoints = out.numberofpoints;
  bg.pointlist = out.pointlist;
  out.pointlist = nullptr;
  bg.numberoftetrahedra = out.numberoftetrahedra;
  bg.numberofcorners = 4;
  bg.tetrahedronlist = out.tetrahedronlist;
  out.tetrahedronlist = nullptr;
  bg.numberofpointmtrs = 1;
  bg.pointmtrlist = new REAL[sizes.size()];
  std::copy(sizes.begin(), sizes.end(), bg.pointmtrlist);
}

// TetGen's switches: ours from the quality bounds, or the caller's with the ones molmesh
// needs added.
std::string tetgen_switches(const TetMeshOptions& options, bool graded) {
  // p: PLC; Y: no Steiner points on the given facets; M: keep coplanar neighbours as
  // separate facets (merging them would let TetGen re-triangulate the surface); z: 0-based;
  // n: neighbours (to split regions); Q: quiet.
  std::string switches;
  if (options.tetgen_switches.empty()) {
    if (!(options.max_radius_edge_ratio > 0.0) || options.min_dihedral_deg < 0.0)
      throw Error("tetgen quality bounds must be positive");
    switches = "pYM";
    switches += "q" + format_number(options.max_radius_edge_ratio) + "/" +
                format_number(options.min_dihedral_deg);
    if (options.max_volume) {
      if (!(*options.max_volume > 0.0)) throw Error("maximum tetrahedron volume must be positive");
      switches += "a" + format_number(*options.max_volume);
    }
    if (graded) switches += "m";
  } else {
    switches = options.tetgen_switches;
    if (switches.find_first_of("rRwmk") != std::string::npos)
      throw OptionError(
          "`tetgen_switches`: r, R, w, m and k are not supported (molmesh meshes a PLC)");
    if (switches.find('p') == std::string::npos) switches.insert(0, "p");
  }
  for (char c : std::string("znQ"))
    if (switches.find(c) == std::string::npos) switches += c;
  return switches;
}

}  // namespace

std::string domain_name(Domain domain) {
  switch (domain) {
    case Domain::interior:
      return "interior";
    case Domain::exterior:
      return "exterior";
    case Domain::full:
      return "full";
  }
  return "full";
}

void TetMeshOptions::validate() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw OptionError(what);
  };
  require(std::isfinite(sphere_ratio) && sphere_ratio > 0.0 && sphere_ratio <= kMaxSphereRatio,
          "the sphere ratio (`sphere_ratio`) must be a finite number in (0, " +
              format_number(kMaxSphereRatio) + "]");
  if (outer_radius)
    require(std::isfinite(*outer_radius) && *outer_radius > 0.0 && *outer_radius <= kMaxOuterRadius,
            "the outer sphere radius (`outer_radius`) must be a finite number in (0, " +
                format_number(kMaxOuterRadius) + "] Å");
  require(
      outer_sphere_subdivisions >= 0 && outer_sphere_subdivisions <= kMaxOuterSphereSubdivisions,
      "the outer sphere subdivision level (`outer_sphere_subdivisions`) must be 0.." +
          std::to_string(kMaxOuterSphereSubdivisions));
  require(std::isfinite(max_radius_edge_ratio) && max_radius_edge_ratio >= kMinRadiusEdgeRatio &&
              max_radius_edge_ratio <= kMaxRadiusEdgeRatio,
          "the radius-edge bound (`max_radius_edge_ratio`) must be a finite number in [" +
              format_number(kMinRadiusEdgeRatio) + ", " + format_number(kMaxRadiusEdgeRatio) +
              "] (TetGen may not terminate below 1)");
  require(std::isfinite(min_dihedral_deg) && min_dihedral_deg >= 0.0 &&
              min_dihedral_deg <= kMaxMinDihedralDeg,
          "the minimum dihedral angle (`min_dihedral_deg`) must be a finite number in [0, " +
              format_number(kMaxMinDihedralDeg) + "] degrees");
  if (max_volume)
    require(std::isfinite(*max_volume) && *max_volume > 0.0,
            "the maximum tetrahedron volume (`max_volume`) must be a finite positive number");
  require(std::isfinite(size_factor) && size_factor >= 0.0 && size_factor <= kMaxSizeFactor,
          "the size factor (`size_factor`) must be a finite number in [0, " +
              format_number(kMaxSizeFactor) + "] (0: no grading)");
  require(std::isfinite(surface_size_ratio) && surface_size_ratio > 0.0 &&
              surface_size_ratio <= kMaxSurfaceSizeRatio,
          "the surface size ratio (`surface_size_ratio`) must be a finite number in (0, " +
              format_number(kMaxSurfaceSizeRatio) + "]");
  require(std::isfinite(max_memory_bytes) && max_memory_bytes > 0.0,
          "the memory limit (`max_memory_bytes`) must be positive");
  for (const auto& s : active_site)
    require(s.center.allFinite() && std::isfinite(s.radius) && s.radius >= 0.0,
            "an active-site sphere has a non-finite centre or radius");
}

namespace {

// What the steps below need to know of the molecule.
struct MoleculeMeasures {
  MoleculeExtent extent;
  double surface_reach = 0.0;  // how far the surface reaches from the centre (Å)
  double volume = 0.0;         // enclosed by the surface (Å³)
  double field_radius = 0.0;   // where the far field's size law starts (size_field.hpp)
};

MoleculeMeasures measure_molecule(const SurfaceMesh& surface, const Atoms& atoms) {
  MoleculeMeasures m;
  m.extent = atoms.empty() ? molecule_extent(surface.points) : molecule_extent(atoms);
  for (const auto& p : surface.points)
    m.surface_reach = std::max(m.surface_reach, (p - m.extent.centroid).norm());
  m.volume = std::abs(enclosed_volume(surface.points, surface.triangles));
  m.field_radius = size_field_radius(m.volume);
  return m;
}

// The outer sphere of an exterior or full mesh: the given radius, or sphere_ratio times the
// molecule's size; it must enclose the surface.
SurfaceMesh outer_sphere(const MoleculeMeasures& m, const TetMeshOptions& options,
                         TetMeshReport& report) {
  double radius = 0.0;
  if (options.outer_radius) {
    radius = *options.outer_radius;
  } else {
    if (!(options.sphere_ratio > 0.0)) throw Error("the sphere ratio must be positive");
    radius = options.sphere_ratio * m.extent.size;
    if (!(radius > 0.0))
      throw Error(
          "the molecule has zero size (a single atom?): give the outer sphere "
          "radius explicitly (`outer_radius`)");
  }
  // 5 % slack: the icosphere's flat faces sit slightly inside the true sphere.
  if (!(radius > m.surface_reach * 1.05))
    throw Error("the outer sphere (radius " + format_number(radius) +
                " Å) does not enclose the molecular surface (reaching " +
                format_number(m.surface_reach) + " Å from the centre); increase it");
  SurfaceMesh sphere = icosphere(m.extent.centroid, radius, options.outer_sphere_subdivisions);
  report.outer_radius = radius;
  report.outer_sphere_vertices = sphere.points.size();
  return sphere;
}

// The target size of every input vertex (surface, then sphere) for TetGen's -m, capped at
// size_cap when that is positive; first the memory the mesh will take is checked against
// the limit.
std::vector<double> vertex_sizes(const SurfaceMesh& surface, int n_in, const MoleculeMeasures& m,
                                 bool want_exterior, const TetMeshOptions& options,
                                 double outer_radius, double size_cap) {
  const int n_surface = static_cast<int>(surface.points.size());
  // The size rule (size_field.hpp): surface vertices from their edges, the outer sphere's
  // from the far-field law (its triangles bound the tetrahedra resting on it anyway).
  std::vector<double> sizes = mean_edge_lengths(surface);
  for (double& h : sizes) h *= options.surface_size_ratio;
  sizes.resize(static_cast<std::size_t>(n_in), far_field_size(outer_radius, m.field_radius));
  for (double& h : sizes) h *= options.size_factor;
  // The molecule's volume at the surface's sizes needs about volume / (h^3 / 8.5)
  // tetrahedra of edge h (a regular tetrahedron has volume h^3 / 8.49): the interior, or
  // as much solvent along the surface; plus the far field's. Checked against the memory
  // limit before TetGen allocates (--size-factor 1e-3 ran for minutes).
  double h_mean = 0.0;
  for (int i = 0; i < n_surface; ++i) h_mean += sizes[static_cast<std::size_t>(i)];
  h_mean /= n_surface;
  double tetrahedra = m.volume * kTetrahedraPerCube / (h_mean * h_mean * h_mean);
  if (want_exterior)
    tetrahedra +=
        far_field_tetrahedra(m.surface_reach, m.field_radius, outer_radius, options.size_factor);
  check_memory(tetrahedra * kBytesPerTetrahedron, options.max_memory_bytes,
               "the tetrahedral mesh (about " + format_number(tetrahedra) +
                   " tetrahedra at `size_factor` " + format_number(options.size_factor) + ")",
               "raise `size_factor`");
  // After the estimate: a max_volume too small is refused by its own estimate later.
  if (size_cap > 0.0)
    for (double& h : sizes) h = std::min(h, size_cap);
  return sizes;
}

// Atom centres become nodes of the molecule's part. They go into the PLC as isolated
// vertices, which TetGen puts into its initial Delaunay tetrahedralisation. (Inserting
// them afterwards with -i crashes TetGen 1.5 in insertconstrainedpoints on mAChE.)
// Duplicates would be rejected by TetGen, so they are merged here, and so are centres on a
// surface vertex (both counted in report.coincident_atoms).
std::vector<Vec3> atom_nodes(const SurfaceMesh& surface, const Atoms& atoms,
                             TetMeshReport& report) {
  std::vector<Vec3> nodes;
  std::unordered_set<std::array<std::uint64_t, 3>, PointKeyHash> seen;
  std::unordered_set<std::array<std::uint64_t, 3>, PointKeyHash> surface_keys;
  for (const auto& p : surface.points) surface_keys.insert(point_key(p));
  for (const auto& a : atoms) {
    const auto key = point_key(a.center);
    if (!seen.insert(key).second || surface_keys.count(key)) {
      ++report.coincident_atoms;
      continue;
    }
    nodes.push_back(a.center);
  }
  return nodes;
}

// Exterior meshes: the molecule's inside is a hole, so TetGen does not refine it only for
// the classification to drop it (mAChE's level 0: TetGen 15.9 -> 5.8 s). Hole points are
// atom centres that the molecular surface's winding number puts inside the molecule (not
// in a cavity); a few spread over the atom list cover multi-part molecules. A part without
// a hole point is meshed and dropped as before.
std::vector<Vec3> molecule_holes(const SurfaceMesh& surface, const Atoms& atoms) {
  std::vector<Vec3> holes;
  const std::size_t step = std::max<std::size_t>(1, atoms.size() / kMaxHolePoints);
  for (std::size_t i = 0; i < atoms.size() && holes.size() < kMaxHolePoints; i += step)
    if (winding_number(surface.points, surface.triangles, atoms[i].center) > 0.5)
      holes.push_back(atoms[i].center);
  return holes;
}

// Appends isolated nodes to TetGen's input, the vertex sizes when there are any (a node
// takes none of its own: 0 lets TetGen interpolate one), and the hole points, if any are
// given (`holes` non-null).
void complete_input(const std::vector<Vec3>& nodes, const std::vector<double>& sizes,
                    const std::vector<Vec3>* holes, tetgenio& in) {
  const int n_in = in.numberofpoints;
  if (!nodes.empty()) {
    const std::size_t n_all = static_cast<std::size_t>(n_in) + nodes.size();
    auto* all_points = new REAL[n_all * 3];
    std::copy(in.pointlist, in.pointlist + static_cast<std::size_t>(n_in) * 3, all_points);
    for (std::size_t i = 0; i < nodes.size(); ++i)
      for (int d = 0; d < 3; ++d) all_points[3 * (n_in + i) + d] = nodes[i][d];
    delete[] in.pointlist;
    in.pointlist = all_points;
    in.numberofpoints = static_cast<int>(n_all);
  }
  if (!sizes.empty()) {
    in.numberofpointmtrs = 1;
    in.pointmtrlist = new REAL[static_cast<std::size_t>(in.numberofpoints)];
    for (int i = 0; i < in.numberofpoints; ++i)
      in.pointmtrlist[i] = i < n_in ? sizes[static_cast<std::size_t>(i)] : 0.0;
  }
  if (holes) {
    in.numberofholes = static_cast<int>(holes->size());
    in.holelist = new REAL[holes->size() * 3];
    for (std::size_t i = 0; i < holes->size(); ++i)
      for (int d = 0; d < 3; ++d) in.holelist[3 * i + d] = (*holes)[i][d];
  }
}

// The solvent's sizes: a background mesh through the surface, the outer sphere and the
// far-field shells, all with their sizes (`vertex_sizes` holds the surface's and the
// sphere's).
void solvent_background(const SurfaceMesh& surface, const SurfaceMesh& sphere,
                        const std::vector<double>& vertex_sizes, const MoleculeMeasures& m,
                        const TetMeshOptions& options, double outer_radius, double size_cap,
                        tetgenio& background) {
  const int n_surface = static_cast<int>(surface.points.size());
  const int n_in = n_surface + static_cast<int>(sphere.points.size());
  const SizePoints shells = far_field_size_points(
      m.extent.centroid, m.surface_reach, m.field_radius, outer_radius, options.size_factor);
  std::vector<Vec3> points = surface.points;
  points.insert(points.end(), sphere.points.begin(), sphere.points.end());
  points.insert(points.end(), shells.points.begin(), shells.points.end());
  std::vector<double> sizes(vertex_sizes.begin(), vertex_sizes.begin() + n_in);
  sizes.insert(sizes.end(), shells.sizes.begin(), shells.sizes.end());
  // The centre too, with the surface's mean size: the Delaunay tetrahedralisation of a
  // surface's vertices alone is degenerate when they are cospherical (an icosphere input).
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& p : surface.points) nearest = std::min(nearest, (p - m.extent.centroid).norm());
  if (nearest > 1e-6 * m.surface_reach) {
    double mean = 0.0;
    for (int i = 0; i < n_surface; ++i) mean += sizes[static_cast<std::size_t>(i)];
    points.push_back(m.extent.centroid);
    sizes.push_back(mean / n_surface);
  }
  if (size_cap > 0.0)
    for (double& h : sizes) h = std::min(h, size_cap);
  if (!shells.points.empty()) background_mesh(points, sizes, background);
}

// One TetGen run; TetGen's errors become molmesh::Error.
void run_tetgen(const std::string& switches, tetgenio& in, tetgenio& background, tetgenio& out) {
  tetgenbehavior behavior;
  std::string switch_buffer = switches;
  if (!behavior.parse_commandline(switch_buffer.data()))
    throw Error("TetGen rejected the switches \"" + switches + "\"");
  detail::link_tetgen_terminate_override();
  try {
    ::tetrahedralize(&behavior, &in, &out, nullptr,
                     background.numberofpoints > 0 ? &background : nullptr);
  } catch (int code) {
    throw Error("tetrahedral meshing failed: " + tetgen_error_message(code));
  }
}

// How many of the atom nodes the mesh kept (the others fell outside the molecule's part).
void count_atom_nodes(const TetMesh& mesh, const std::vector<Vec3>& nodes, TetMeshReport& report) {
  std::unordered_set<std::array<std::uint64_t, 3>, PointKeyHash> kept;
  kept.reserve(mesh.points.size() * 2);
  for (const auto& p : mesh.points) kept.insert(point_key(p));
  for (const auto& c : nodes) {
    if (kept.count(point_key(c)))
      ++report.atoms_as_nodes;
    else
      ++report.atoms_outside;
  }
}

// tetrahedralize() in a frame centred on the molecule (see there).
TetMesh tetrahedralize_centred(const SurfaceMesh& surface, const Atoms& atoms,
                               const TetMeshOptions& options, const Reporter& reporter,
                               TetMeshReport* report_out) {
  const auto t_start = Clock::now();
  TetMeshReport report;
  const bool want_interior = options.domain != Domain::exterior;
  const bool want_exterior = options.domain != Domain::interior;
  const MoleculeMeasures molecule = measure_molecule(surface, atoms);
  report.molecule_size = molecule.extent.size;
  report.surface_vertices = surface.points.size();
  report.atoms_given = atoms.size();

  const SurfaceMesh sphere =
      want_exterior ? outer_sphere(molecule, options, report) : SurfaceMesh{};
  // Surface facets first (their indices are kept by TetGen), then the sphere.
  const int n_in = static_cast<int>(surface.points.size() + sphere.points.size());
  tetgenio in;
  detail::fill_plc(surface, sphere, options.active_site, in);

  const bool graded = options.size_factor > 0.0 && options.tetgen_switches.empty();
  // With max_volume, no size above the edge of a tetrahedron of that volume (h³ / 8.49):
  // TetGen rejects a refinement point that falls inside a vertex's size, which left
  // tetrahedra above the bound once surface sizes were 1.5 edges.
  const double size_cap =
      options.max_volume ? std::cbrt(kTetrahedraPerCube * *options.max_volume) : 0.0;
  const std::vector<double> sizes = graded ? vertex_sizes(surface, n_in, molecule, want_exterior,
                                                          options, report.outer_radius, size_cap)
                                           : std::vector<double>{};
  const std::vector<Vec3> nodes =
      want_interior && !atoms.empty() ? atom_nodes(surface, atoms, report) : std::vector<Vec3>{};
  const bool with_holes = !want_interior && !atoms.empty();
  const std::vector<Vec3> holes = with_holes ? molecule_holes(surface, atoms) : std::vector<Vec3>{};
  complete_input(nodes, sizes, with_holes ? &holes : nullptr, in);
  tetgenio background;
  if (graded && want_exterior)
    solvent_background(surface, sphere, sizes, molecule, options, report.outer_radius, size_cap,
                       background);

  const std::string switches = tetgen_switches(options, graded);
  report.tetgen_switches = switches;
  if (options.max_volume && options.tetgen_switches.empty()) {
    // Every tetrahedron is at most max_volume, so the domain needs at least volume / bound.
    const double domain_volume =
        want_exterior ? 4.0 / 3.0 * std::numbers::pi * std::pow(report.outer_radius, 3)
                      : molecule.volume;
    const double tetrahedra = domain_volume / *options.max_volume;
    check_memory(tetrahedra * kBytesPerTetrahedron, options.max_memory_bytes,
                 "the tetrahedral mesh (at least " + format_number(tetrahedra) +
                     " tetrahedra at `max_volume` " + format_number(*options.max_volume) + ")",
                 "raise `max_volume`");
  }

  tetgenio out;
  const auto t_tetgen = Clock::now();
  run_tetgen(switches, in, background, out);
  report.seconds = seconds_since(t_tetgen);
  reporter.progress("tetrahedralize", 0.8);

  detail::TetGenOutputOptions extract;
  extract.keep_molecule = want_interior;
  extract.keep_solvent = want_exterior;
  extract.input_points = n_in;
  TetMesh mesh = detail::mesh_from_tetgen(out, surface, extract, &report.surface_steiner_points);

  if (!nodes.empty()) {
    count_atom_nodes(mesh, nodes, report);
    if (report.atoms_outside > 0)
      reporter.warn(std::to_string(report.atoms_outside) +
                    " atom centres lie outside the molecular surface (or too close to it) and "
                    "are not mesh nodes");
  }
  if (report.surface_steiner_points > 0)
    reporter.warn("TetGen added " + std::to_string(report.surface_steiner_points) +
                  " points on the molecular surface");

  report.total_seconds = seconds_since(t_start);
  reporter.progress("tetrahedralize", 1.0);
  if (report_out) *report_out = report;
  return mesh;
}

}  // namespace

TetMesh tetrahedralize(const SurfaceMesh& surface, const Atoms& atoms,
                       const TetMeshOptions& options, const Reporter& reporter,
                       TetMeshReport* report_out) {
  if (surface.triangles.empty() || surface.points.empty())
    throw Error("cannot tetrahedralize an empty surface");
  validate_plc(surface);
  options.validate();
  for (const auto& a : atoms)
    if (!a.center.allFinite()) throw Error("an atom has a non-finite position");
  reporter.progress("tetrahedralize", 0.0);

  // Local frame: TetGen's tolerances and our exact point matching work best with
  // coordinates near the origin, and the mesh must not depend on where the molecule sits
  // (issue 18: far from the origin results degraded). Shift to the molecule's centre,
  // mesh, shift back.
  const Vec3 centre =
      (atoms.empty() ? molecule_extent(surface.points) : molecule_extent(atoms)).centroid;
  SurfaceMesh local = surface;
  for (auto& p : local.points) p -= centre;
  Atoms local_atoms = atoms;
  for (auto& a : local_atoms) a.center -= centre;
  TetMeshOptions local_options = options;
  for (auto& sphere : local_options.active_site) sphere.center -= centre;
  TetMesh mesh = tetrahedralize_centred(local, local_atoms, local_options, reporter, report_out);
  for (auto& p : mesh.points) p += centre;
  return mesh;
}

}  // namespace molmesh
