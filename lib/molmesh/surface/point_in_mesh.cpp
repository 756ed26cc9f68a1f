#include "molmesh/surface/point_in_mesh.hpp"

#include <algorithm>
#include <cmath>

namespace molmesh {

PointInMesh::PointInMesh(const SurfaceMesh& mesh) : mesh_(&mesh) {
  if (mesh.triangles.empty()) return;
  double y1 = -1e300, z1 = -1e300;
  y0_ = z0_ = 1e300;
  double edge_sum = 0.0;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = mesh.points[static_cast<std::size_t>(t[k])];
      y0_ = std::min(y0_, p.y());
      z0_ = std::min(z0_, p.z());
      y1 = std::max(y1, p.y());
      z1 = std::max(z1, p.z());
      edge_sum += (mesh.points[static_cast<std::size_t>(t[(k + 1) % 3])] - p).norm();
    }
  // Buckets about two mean edges wide keep a few triangles per bucket.
  cell_ = std::max(2.0 * edge_sum / (3.0 * static_cast<double>(mesh.triangles.size())), 1e-9);
  ny_ = std::max(1, static_cast<int>((y1 - y0_) / cell_) + 1);
  nz_ = std::max(1, static_cast<int>((z1 - z0_) / cell_) + 1);
  const std::size_t buckets = static_cast<std::size_t>(ny_) * static_cast<std::size_t>(nz_);
  start_.assign(buckets + 1, 0);
  auto range = [&](const Triangle& t, int& iy0, int& iy1, int& iz0, int& iz1) {
    double ylo = 1e300, yhi = -1e300, zlo = 1e300, zhi = -1e300;
    for (int v : t) {
      const Vec3& p = mesh.points[static_cast<std::size_t>(v)];
      ylo = std::min(ylo, p.y());
      yhi = std::max(yhi, p.y());
      zlo = std::min(zlo, p.z());
      zhi = std::max(zhi, p.z());
    }
    iy0 = std::clamp(static_cast<int>((ylo - y0_) / cell_), 0, ny_ - 1);
    iy1 = std::clamp(static_cast<int>((yhi - y0_) / cell_), 0, ny_ - 1);
    iz0 = std::clamp(static_cast<int>((zlo - z0_) / cell_), 0, nz_ - 1);
    iz1 = std::clamp(static_cast<int>((zhi - z0_) / cell_), 0, nz_ - 1);
  };
  for (const Triangle& t : mesh.triangles) {
    int iy0, iy1, iz0, iz1;
    range(t, iy0, iy1, iz0, iz1);
    for (int iz = iz0; iz <= iz1; ++iz)
      for (int iy = iy0; iy <= iy1; ++iy) ++start_[static_cast<std::size_t>(iz * ny_ + iy) + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
  items_.resize(static_cast<std::size_t>(start_.back()));
  std::vector<int> fill(start_.begin(), start_.end() - 1);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    int iy0, iy1, iz0, iz1;
    range(mesh.triangles[f], iy0, iy1, iz0, iz1);
    for (int iz = iz0; iz <= iz1; ++iz)
      for (int iy = iy0; iy <= iy1; ++iy)
        items_[static_cast<std::size_t>(fill[static_cast<std::size_t>(iz * ny_ + iy)]++)] =
            static_cast<int>(f);
  }
}

// Signed crossings of the ray from (x, y, z) towards +x; a large sentinel when the ray
// passes exactly through an edge or vertex (the caller then nudges it).
int PointInMesh::count_crossings(double y, double z, double x) const {
  constexpr int kDegenerate = 1 << 30;
  const int iy = static_cast<int>(std::floor((y - y0_) / cell_));
  const int iz = static_cast<int>(std::floor((z - z0_) / cell_));
  if (iy < 0 || iz < 0 || iy >= ny_ || iz >= nz_) return 0;
  const std::size_t b = static_cast<std::size_t>(iz * ny_ + iy);
  int winding = 0;
  for (int q = start_[b]; q < start_[b + 1]; ++q) {
    const Triangle& t =
        mesh_->triangles[static_cast<std::size_t>(items_[static_cast<std::size_t>(q)])];
    const Vec3& a = mesh_->points[static_cast<std::size_t>(t[0])];
    const Vec3& p = mesh_->points[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh_->points[static_cast<std::size_t>(t[2])];
    // Edge functions in the (y, z) plane; all the sign of the projected area when inside.
    const double w0 = (p.y() - y) * (c.z() - z) - (p.z() - z) * (c.y() - y);
    const double w1 = (c.y() - y) * (a.z() - z) - (c.z() - z) * (a.y() - y);
    const double w2 = (a.y() - y) * (p.z() - z) - (a.z() - z) * (p.y() - y);
    const bool pos = w0 > 0 && w1 > 0 && w2 > 0;
    const bool neg = w0 < 0 && w1 < 0 && w2 < 0;
    if (!pos && !neg) {
      const bool touches = (w0 == 0 || w1 == 0 || w2 == 0) &&
                           ((w0 >= 0 && w1 >= 0 && w2 >= 0) || (w0 <= 0 && w1 <= 0 && w2 <= 0));
      if (touches) {
        const double sum = w0 + w1 + w2;
        if (sum == 0.0) continue;  // edge-on triangle: the ray grazes it
        const double xi = (w0 * a.x() + w1 * p.x() + w2 * c.x()) / sum;
        if (xi > x) return kDegenerate;
      }
      continue;
    }
    const double sum = w0 + w1 + w2;
    const double xi = (w0 * a.x() + w1 * p.x() + w2 * c.x()) / sum;
    if (xi > x) winding += pos ? 1 : -1;
  }
  return winding;
}

int PointInMesh::winding_number(const Vec3& p) const {
  if (mesh_->triangles.empty()) return 0;
  // Deterministic nudges (a fraction of a bucket) for rays through edges or vertices.
  for (int attempt = 0; attempt < 16; ++attempt) {
    const double dy = attempt == 0 ? 0.0 : cell_ * 1e-4 * std::sin(1.3 * attempt);
    const double dz = attempt == 0 ? 0.0 : cell_ * 1e-4 * std::cos(2.1 * attempt);
    const int w = count_crossings(p.y() + dy, p.z() + dz, p.x());
    if (w != (1 << 30)) return w;
  }
  return 0;
}

}  // namespace molmesh
