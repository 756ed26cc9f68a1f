#include "solvers/fem/point_locator.hpp"

#include <algorithm>
#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

namespace molmesh::solvers {

namespace bg = boost::geometry;
namespace bgi = boost::geometry::index;
using Point = bg::model::point<double, 3, bg::cs::cartesian>;
using Box = bg::model::box<Point>;
using Entry = std::pair<Box, int>;  // a cell's bounding box and its index

struct PointLocator::Index {
  bgi::rtree<Entry, bgi::rstar<16>> tree;
  double tolerance = 0.0;  // how far outside a box a point may lie and still be tested
};

namespace {

// Barycentric coordinates from the inverse Jacobian (rows: the gradients of the last three
// coordinates), as the P1 assembly computes them.
std::array<double, 4> barycentric(const TetMesh& mesh, const Tetrahedron& tet, const Vec3& p) {
  const Vec3& a = mesh.points[static_cast<std::size_t>(tet[0])];
  const Vec3 e1 = mesh.points[static_cast<std::size_t>(tet[1])] - a;
  const Vec3 e2 = mesh.points[static_cast<std::size_t>(tet[2])] - a;
  const Vec3 e3 = mesh.points[static_cast<std::size_t>(tet[3])] - a;
  const double det = e1.dot(e2.cross(e3));
  const Vec3 d = p - a;
  const double l1 = e2.cross(e3).dot(d) / det;
  const double l2 = e3.cross(e1).dot(d) / det;
  const double l3 = e1.cross(e2).dot(d) / det;
  return {1.0 - l1 - l2 - l3, l1, l2, l3};
}

}  // namespace

PointLocator::PointLocator(const TetMesh& mesh) : mesh_(&mesh), index_(std::make_unique<Index>()) {
  std::vector<Entry> boxes;
  boxes.reserve(mesh.tetrahedra.size());
  double extent = 0.0;
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const Tetrahedron& tet = mesh.tetrahedra[t];
    Vec3 lo = mesh.points[static_cast<std::size_t>(tet[0])], hi = lo;
    for (int v : tet) {
      lo = lo.cwiseMin(mesh.points[static_cast<std::size_t>(v)]);
      hi = hi.cwiseMax(mesh.points[static_cast<std::size_t>(v)]);
    }
    extent = std::max(extent, (hi - lo).maxCoeff());
    boxes.emplace_back(Box(Point(lo.x(), lo.y(), lo.z()), Point(hi.x(), hi.y(), hi.z())),
                       static_cast<int>(t));
  }
  index_->tolerance = 1e-9 * std::max(extent, 1.0);
  // The range constructor bulk-loads (packing): faster to build and to query than inserts.
  index_->tree = bgi::rtree<Entry, bgi::rstar<16>>(boxes.begin(), boxes.end());
}

PointLocator::~PointLocator() = default;
PointLocator::PointLocator(PointLocator&&) noexcept = default;
PointLocator& PointLocator::operator=(PointLocator&&) noexcept = default;

std::optional<PointLocation> PointLocator::locate(const Vec3& p) const {
  const double e = index_->tolerance;
  const Box probe(Point(p.x() - e, p.y() - e, p.z() - e), Point(p.x() + e, p.y() + e, p.z() + e));
  std::vector<Entry> candidates;
  index_->tree.query(bgi::intersects(probe), std::back_inserter(candidates));
  // Keep the cell whose smallest barycentric coordinate is largest: the containing one,
  // robust to rounding for points on faces and vertices. Ties go to the lowest cell index,
  // so the answer does not depend on the tree's internal order.
  std::sort(candidates.begin(), candidates.end(),
            [](const Entry& x, const Entry& y) { return x.second < y.second; });
  PointLocation best;
  double best_min = -1e300;
  for (const Entry& candidate : candidates) {
    const auto t = static_cast<std::size_t>(candidate.second);
    const auto l = barycentric(*mesh_, mesh_->tetrahedra[t], p);
    const double m = std::min(std::min(l[0], l[1]), std::min(l[2], l[3]));
    if (m > best_min) {
      best_min = m;
      best.tetrahedron = candidate.second;
      best.barycentric = l;
    }
  }
  if (best.tetrahedron < 0 || best_min < -1e-9) return std::nullopt;
  return best;
}

}  // namespace molmesh::solvers
