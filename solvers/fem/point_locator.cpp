#include "solvers/fem/point_locator.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace molmesh::solvers {

namespace {

std::array<double, 4> barycentric(const TetMesh& mesh, const Tetrahedron& tet, const Vec3& p) {
  const Vec3& a = mesh.points[static_cast<std::size_t>(tet[0])];
  Eigen::Matrix3d m;
  m.col(0) = mesh.points[static_cast<std::size_t>(tet[1])] - a;
  m.col(1) = mesh.points[static_cast<std::size_t>(tet[2])] - a;
  m.col(2) = mesh.points[static_cast<std::size_t>(tet[3])] - a;
  const Vec3 l = m.partialPivLu().solve(p - a);
  return {1.0 - l.sum(), l[0], l[1], l[2]};
}

}  // namespace

PointLocator::PointLocator(const TetMesh& mesh) : mesh_(&mesh) {
  const std::size_t nt = mesh.tetrahedra.size();
  if (nt == 0) return;
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const Vec3 extent = (hi - lo).cwiseMax(1e-9);
  // About two cells per bucket on average keeps both the lists and the scan short.
  const double volume = extent.prod();
  cell_ = std::cbrt(2.0 * volume / static_cast<double>(nt));
  lower_ = lo;
  for (int d = 0; d < 3; ++d) {
    dims_[static_cast<std::size_t>(d)] =
        std::clamp(static_cast<int>(std::ceil(extent[d] / cell_)), 1, 1024);
  }
  const std::size_t nb =
      static_cast<std::size_t>(dims_[0]) * static_cast<std::size_t>(dims_[1]) * dims_[2];
  auto bucket_range = [&](const Tetrahedron& tet, std::array<int, 3>& b0, std::array<int, 3>& b1) {
    Vec3 tlo = mesh.points[static_cast<std::size_t>(tet[0])], thi = tlo;
    for (int v : tet) {
      tlo = tlo.cwiseMin(mesh.points[static_cast<std::size_t>(v)]);
      thi = thi.cwiseMax(mesh.points[static_cast<std::size_t>(v)]);
    }
    for (int d = 0; d < 3; ++d) {
      const auto du = static_cast<std::size_t>(d);
      b0[du] = std::clamp(static_cast<int>((tlo[d] - lower_[d]) / cell_), 0, dims_[du] - 1);
      b1[du] = std::clamp(static_cast<int>((thi[d] - lower_[d]) / cell_), 0, dims_[du] - 1);
    }
  };
  auto index = [&](int i, int j, int k) {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(dims_[0]) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(dims_[1]) * k);
  };
  std::vector<int> count(nb + 1, 0);
  std::array<int, 3> b0{}, b1{};
  for (const Tetrahedron& tet : mesh.tetrahedra) {
    bucket_range(tet, b0, b1);
    for (int k = b0[2]; k <= b1[2]; ++k)
      for (int j = b0[1]; j <= b1[1]; ++j)
        for (int i = b0[0]; i <= b1[0]; ++i) ++count[index(i, j, k) + 1];
  }
  for (std::size_t b = 0; b < nb; ++b) count[b + 1] += count[b];
  start_ = count;
  cells_.resize(static_cast<std::size_t>(count[nb]));
  std::vector<int> fill(count.begin(), count.end() - 1);
  for (std::size_t t = 0; t < nt; ++t) {
    bucket_range(mesh.tetrahedra[t], b0, b1);
    for (int k = b0[2]; k <= b1[2]; ++k)
      for (int j = b0[1]; j <= b1[1]; ++j)
        for (int i = b0[0]; i <= b1[0]; ++i)
          cells_[static_cast<std::size_t>(fill[index(i, j, k)]++)] = static_cast<int>(t);
  }
}

std::optional<PointLocation> PointLocator::locate(const Vec3& p) const {
  if (start_.empty()) return std::nullopt;
  std::array<int, 3> b{};
  for (int d = 0; d < 3; ++d) {
    const double f = (p[d] - lower_[d]) / cell_;
    const auto du = static_cast<std::size_t>(d);
    if (f < -1.0 || f > dims_[du] + 1.0) return std::nullopt;
    b[du] = std::clamp(static_cast<int>(f), 0, dims_[du] - 1);
  }
  const std::size_t bucket =
      static_cast<std::size_t>(b[0]) +
      static_cast<std::size_t>(dims_[0]) *
          (static_cast<std::size_t>(b[1]) + static_cast<std::size_t>(dims_[1]) * b[2]);
  // Keep the cell whose smallest barycentric coordinate is largest: the containing one,
  // robust to rounding for points on faces and vertices.
  PointLocation best;
  double best_min = -1e300;
  for (int c = start_[bucket]; c < start_[bucket + 1]; ++c) {
    const auto t = static_cast<std::size_t>(cells_[static_cast<std::size_t>(c)]);
    const auto l = barycentric(*mesh_, mesh_->tetrahedra[t], p);
    const double m = std::min(std::min(l[0], l[1]), std::min(l[2], l[3]));
    if (m > best_min) {
      best_min = m;
      best.tetrahedron = static_cast<int>(t);
      best.barycentric = l;
    }
  }
  if (best.tetrahedron < 0 || best_min < -1e-9) return std::nullopt;
  return best;
}

}  // namespace molmesh::solvers
