#include "solvers/fem/point_locator.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>
#include <vector>

#include "molmesh/geometry/box_index.hpp"
#include "molmesh/geometry/tetrahedron.hpp"

namespace molmesh::solvers {

struct PointLocator::Index {
  BoxIndex boxes;          // the cells' bounding boxes
  double tolerance = 0.0;  // how far outside a box a point may lie and still be tested
};

PointLocator::PointLocator(const TetMesh& mesh) : mesh_(&mesh), index_(std::make_unique<Index>()) {
  std::vector<Box3> boxes;
  boxes.reserve(mesh.tetrahedra.size());
  double extent = 0.0;
  for (const Tetrahedron& tet : mesh.tetrahedra) {
    Box3 box;
    for (int v : tet) box.extend(mesh.points[static_cast<std::size_t>(v)]);
    extent = std::max(extent, box.sizes().maxCoeff());
    boxes.push_back(box);
  }
  index_->tolerance = 1e-9 * std::max(extent, 1.0);
  index_->boxes = BoxIndex(boxes);
}

PointLocator::~PointLocator() = default;
PointLocator::PointLocator(PointLocator&&) noexcept = default;
PointLocator& PointLocator::operator=(PointLocator&&) noexcept = default;

std::optional<PointLocation> PointLocator::locate(const Vec3& p) const {
  const double e = index_->tolerance;
  const Box3 probe(p - Vec3::Constant(e), p + Vec3::Constant(e));
  std::vector<int> candidates;
  index_->boxes.overlapping(probe, [&](int t) { candidates.push_back(t); });
  // Keep the cell whose smallest barycentric coordinate is largest: the containing one,
  // robust to rounding for points on faces and vertices. Ties go to the lowest cell index,
  // so the answer does not depend on the index's internal order.
  std::sort(candidates.begin(), candidates.end());
  PointLocation best;
  double best_min = -1e300;
  for (const int t : candidates) {
    const Tetrahedron& tet = mesh_->tetrahedra[static_cast<std::size_t>(t)];
    const auto P = [&](int k) -> const Vec3& {
      return mesh_->points[static_cast<std::size_t>(tet[static_cast<std::size_t>(k)])];
    };
    const Eigen::Vector4d l = tet_barycentric(P(0), P(1), P(2), P(3), p);
    if (l.minCoeff() > best_min) {
      best_min = l.minCoeff();
      best.tetrahedron = t;
      best.barycentric = {l[0], l[1], l[2], l[3]};
    }
  }
  if (best.tetrahedron < 0 || best_min < -kInsideTolerance) return std::nullopt;
  return best;
}

}  // namespace molmesh::solvers
