#include "molmesh/volume/ses_field.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

#include "molmesh/volume/ball_union.hpp"
#include "molmesh/volume/distance_transform.hpp"

namespace molmesh {
namespace {

// A point within this distance (Å) of a sphere is on it, not buried by its ball. The points
// tested (sphere, circle and triple points) lie on their own spheres to within rounding, far
// inside this, so no test needs to name the balls a point was built from.
constexpr double kBuriedTolerance = 1e-7;

struct Ball {
  Vec3 c;
  double R;
  double buried2;  // (R - kBuriedTolerance)^2: a point closer than this to c is buried
};

// Balls bucketed in cubic cells (compressed rows), for "which balls are near p".
class BallCells {
 public:
  BallCells(std::vector<Ball> balls, double cell) : balls_(std::move(balls)), cell_(cell) {
    lo_ = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -lo_;
    for (const Ball& b : balls_) {
      lo_ = lo_.cwiseMin(b.c);
      hi = hi.cwiseMax(b.c);
    }
    for (int a = 0; a < 3; ++a) n_[a] = static_cast<int>((hi[a] - lo_[a]) / cell_) + 1;
    start_.assign(static_cast<std::size_t>(n_[0]) * n_[1] * n_[2] + 1, 0);
    std::vector<std::size_t> cell_of(balls_.size());
    for (std::size_t b = 0; b < balls_.size(); ++b) {
      cell_of[b] = linear(cell_index(balls_[b].c));
      ++start_[cell_of[b] + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    order_.resize(balls_.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t b = 0; b < balls_.size(); ++b) order_[fill[cell_of[b]]++] = int(b);
  }

  const Ball& ball(int b) const { return balls_[static_cast<std::size_t>(b)]; }

  // Calls f(b) for every ball whose centre's cell is within `reach` of p's cell (a
  // superset of the centres within reach); stops early when f returns false.
  template <class F>
  bool for_each_near(const Vec3& p, double reach, F&& f) const {
    const std::array<int, 3> c = cell_index(p);
    const int w = static_cast<int>(std::ceil(reach / cell_));
    int lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::max(0, c[a] - w);
      hi[a] = std::min(n_[a] - 1, c[a] + w);
    }
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const std::size_t cell = linear({x, y, z});
          for (std::size_t n = start_[cell]; n < start_[cell + 1]; ++n)
            if (!f(order_[n])) return false;
        }
    return true;
  }

 private:
  std::array<int, 3> cell_index(const Vec3& p) const {
    std::array<int, 3> c;
    for (int a = 0; a < 3; ++a)
      c[a] = std::clamp(static_cast<int>(std::floor((p[a] - lo_[a]) / cell_)), 0, n_[a] - 1);
    return c;
  }
  std::size_t linear(const std::array<int, 3>& c) const {
    return static_cast<std::size_t>(c[0]) +
           static_cast<std::size_t>(n_[0]) * (c[1] + static_cast<std::size_t>(n_[1]) * c[2]);
  }

  std::vector<Ball> balls_;
  double cell_;
  Vec3 lo_;
  int n_[3] = {1, 1, 1};
  std::vector<std::size_t> start_;
  std::vector<int> order_;
};

// The SAS geometry around one nearest-E site, shared by every band sample with that site:
// the balls whose sphere passes by it, their pairwise intersection circles and the exposed
// triple intersection points (SAS vertices) among them.
struct Circle {
  Vec3 m, axis;  // centre and unit normal
  double rho;    // radius
  int a, b;      // positions in `near` of the two balls
};
struct SiteGeometry {
  std::vector<int> near;
  std::vector<Circle> circles;
  std::vector<Vec3> vertices;
};

// Exact distance from x (inside the SAS) to the SAS boundary, among the boundary's critical
// points for x built from the balls near x's site (sphere points, the nearest point of
// pairwise intersection circles, triple intersection points).
class BoundaryDistance {
 public:
  BoundaryDistance(const BallCells& cells, double max_radius)
      : cells_(cells), max_radius_(max_radius) {}

  // The site's geometry, from the balls whose sphere passes within `reach` of it.
  void build_site(const Vec3& site, double reach, SiteGeometry& g) const {
    g.near.clear();
    g.circles.clear();
    g.vertices.clear();
    cells_.for_each_near(site, max_radius_ + reach, [&](int b) {
      const Ball& B = cells_.ball(b);
      if (std::abs((site - B.c).norm() - B.R) <= reach) g.near.push_back(b);
      return true;
    });
    const std::size_t n = g.near.size();
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b) {
        const Ball& A = cells_.ball(g.near[a]);
        const Ball& B = cells_.ball(g.near[b]);
        Circle c;
        if (!circle(A, B, c.m, c.axis, c.rho)) continue;
        c.a = int(a);
        c.b = int(b);
        if (!circle_buried_by_near(c, g.near)) g.circles.push_back(c);
        for (std::size_t k = b + 1; k < n; ++k) {
          Vec3 p1, p2;
          if (!triple(A, B, cells_.ball(g.near[k]), p1, p2)) continue;
          for (const Vec3& p : {p1, p2})
            if (!buried_by_near(p, g.near) && exposed(p)) g.vertices.push_back(p);
        }
      }
  }

  // The smallest distance from x to an exposed critical point closer than `best` (or
  // `best`). The nearest exposed vertex bounds it first; then each sphere point and circle
  // point closer than the bound is tested for exposure (the near balls bury most, so they
  // are tried before the full scan) and, when exposed, becomes the bound. A point of circle
  // (a, b) lies on both spheres, so it is at least max(d_a, d_b) from x (d_a = |R_a -
  // |x - c_a||): a circle that cannot beat the bound is skipped unbuilt. The answer is the
  // minimum over the exposed candidates, whatever order they are tried in.
  double operator()(const Vec3& x, const SiteGeometry& g, double best,
                    std::vector<double>& sphere_distance) const {
    for (const Vec3& v : g.vertices) best = std::min(best, (x - v).norm());
    const std::size_t n = g.near.size();
    sphere_distance.resize(n);
    for (std::size_t a = 0; a < n; ++a) {
      const Ball& A = cells_.ball(g.near[a]);
      const Vec3 w = x - A.c;
      const double len = w.norm();
      sphere_distance[a] = std::abs(A.R - len);
      if (sphere_distance[a] >= best || !(len > 0.0)) continue;
      const Vec3 q = A.c + w * (A.R / len);
      if (!buried_by_near(q, g.near) && exposed(q)) best = sphere_distance[a];
    }
    for (const Circle& c : g.circles) {
      if (sphere_distance[std::size_t(c.a)] >= best || sphere_distance[std::size_t(c.b)] >= best)
        continue;
      Vec3 u = x - c.m;
      u -= u.dot(c.axis) * c.axis;
      const double ul = u.norm();
      if (ul < 1e-12)
        u = c.axis.unitOrthogonal();
      else
        u /= ul;
      const Vec3 q = c.m + c.rho * u;
      const double d = (x - q).norm();
      if (d >= best) continue;
      if (!buried_by_near(q, g.near) && exposed(q)) best = d;
    }
    return best;
  }

 private:
  // Whether a ball of `near` buries q: the cheap first test.
  bool buried_by_near(const Vec3& q, const std::vector<int>& near) const {
    for (const int b : near) {
      const Ball& B = cells_.ball(b);
      if ((q - B.c).squaredNorm() < B.buried2) return true;
    }
    return false;
  }

  // Whether one ball of `near` holds the whole circle: then no point of it is exposed, for
  // any sample of the site. The farthest circle point from a centre c is at
  // sqrt(h^2 + (r + rho)^2) (h along the axis, r across it); the margin keeps this a strict
  // subset of what the per-point test would call buried.
  bool circle_buried_by_near(const Circle& c, const std::vector<int>& near) const {
    for (const int b : near) {
      const Ball& B = cells_.ball(b);
      const Vec3 v = B.c - c.m;
      const double h = v.dot(c.axis);
      const double across = std::sqrt(std::max(0.0, v.squaredNorm() - h * h));
      const double reach = B.R - kBuriedTolerance - 1e-9;
      if (reach > 0.0 && h * h + (across + c.rho) * (across + c.rho) < reach * reach) return true;
    }
    return false;
  }

  // Whether no ball buries q.
  bool exposed(const Vec3& q) const {
    return cells_.for_each_near(q, max_radius_, [&](int b) {
      return (q - cells_.ball(b).c).squaredNorm() >= cells_.ball(b).buried2;
    });
  }

  static bool circle(const Ball& A, const Ball& B, Vec3& m, Vec3& axis, double& rho) {
    const Vec3 dc = B.c - A.c;
    const double d = dc.norm();
    if (d <= std::abs(A.R - B.R) || d >= A.R + B.R || d == 0.0) return false;
    axis = dc / d;
    const double a = (d * d + A.R * A.R - B.R * B.R) / (2.0 * d);
    rho = std::sqrt(std::max(0.0, A.R * A.R - a * a));
    m = A.c + a * axis;
    return true;
  }

  static bool triple(const Ball& A, const Ball& B, const Ball& C, Vec3& p1, Vec3& p2) {
    const Vec3 ab = B.c - A.c;
    const double d = ab.norm();
    if (d == 0.0) return false;
    const Vec3 ex = ab / d;
    const Vec3 ac = C.c - A.c;
    const double i = ex.dot(ac);
    Vec3 ey = ac - i * ex;
    const double eyl = ey.norm();
    if (eyl < 1e-9) return false;  // collinear centres: a circle, not points
    ey /= eyl;
    const Vec3 ez = ex.cross(ey);
    const double j = ey.dot(ac);
    const double x = (A.R * A.R - B.R * B.R + d * d) / (2.0 * d);
    const double y = (A.R * A.R - C.R * C.R + i * i + j * j) / (2.0 * j) - (i / j) * x;
    const double z2 = A.R * A.R - x * x - y * y;
    if (z2 < 0.0) return false;
    const double z = std::sqrt(z2);
    p1 = A.c + x * ex + y * ey + z * ez;
    p2 = A.c + x * ex + y * ey - z * ez;
    return true;
  }

  const BallCells& cells_;
  double max_radius_;
};

}  // namespace

Grid ses_field(const Atoms& atoms, double probe, double spacing, const Reporter& reporter,
               double max_memory_bytes) {
  // Per sample: the field, the outside mask, the distance transform's squared distance and
  // nearest site.
  constexpr double kBytesPerSample =
      sizeof(double) + sizeof(char) + sizeof(double) + sizeof(std::int64_t);
  Grid grid = ball_union_grid(atoms, probe, spacing, 3, max_memory_bytes, kBytesPerSample);
  ball_union_onto(atoms, probe, grid, reporter);  // the SAS field, > 0 inside the SAS
  reporter.progress("distance transform", 0.0);
  std::vector<char> outside(grid.size());
  for (std::size_t n = 0; n < grid.size(); ++n) outside[n] = grid.values[n] <= 0.0;
  const DistanceTransform edt = euclidean_distance_transform(outside, grid.dims, grid.spacing);
  reporter.progress("distance transform", 0.5);

  std::vector<Ball> balls;
  double max_radius = 0.0;
  for (const Atom& atom : atoms) {
    if (!(atom.radius > 0.0)) continue;
    const double R = atom.radius + probe;
    balls.push_back({atom.center, R, (R - kBuriedTolerance) * (R - kBuriedTolerance)});
    max_radius = std::max(max_radius, atom.radius + probe);
  }
  const BallCells cells(balls, max_radius);
  const BoundaryDistance boundary_distance(cells, max_radius);

  const double h = grid.spacing.maxCoeff();
  // Lattice distances overestimate dist(x, E) by less than a cell diagonal; samples that
  // could be within a cell of the surface get the exact distance.
  const double band_lo = probe - 1.5 * h;
  const double band_hi = probe + 2.0 * h;
  const double near_reach = 2.0 * h;  // SAS spheres passing this close to the nearest E sample
  const int nx = grid.dims[0], ny = grid.dims[1], nz = grid.dims[2];
  // Lattice values everywhere; the band samples and their nearest E sites are collected per
  // plane (in order, so the result does not depend on threading).
  std::vector<std::vector<std::int64_t>> band(static_cast<std::size_t>(nz));
  tbb::parallel_for(tbb::blocked_range<int>(0, nz, 1), [&](const tbb::blocked_range<int>& r) {
    for (int k = r.begin(); k != r.end(); ++k)
      for (std::size_t n = grid.index(0, 0, k), end = n + std::size_t(nx) * ny; n < end; ++n) {
        if (outside[n]) {
          // dist(x, E) = 0 here; the SAS field keeps the value strictly negative (and
          // exact) when the probe is 0 and the SES is the vdW surface itself.
          grid.values[n] = std::min(grid.values[n], -1e-9 * h) - probe;
          continue;
        }
        const double d = std::sqrt(edt.squared_distance[n]);
        grid.values[n] = d - probe;
        if (d >= band_lo && d <= band_hi && edt.nearest[n] >= 0)
          band[static_cast<std::size_t>(k)].push_back(static_cast<std::int64_t>(n));
      }
  });
  // Band samples grouped by their nearest E site (sorted by site, then sample): each group
  // shares one SiteGeometry, built once (there are ~8 samples per site).
  std::vector<std::pair<std::int64_t, std::int64_t>> samples;  // (site, sample)
  for (const auto& plane : band)
    for (const std::int64_t n : plane) samples.emplace_back(edt.nearest[std::size_t(n)], n);
  band.clear();
  tbb::parallel_sort(samples.begin(), samples.end());
  std::vector<std::size_t> group_start;  // where each site's samples begin, then the end
  for (std::size_t s = 0; s < samples.size(); ++s)
    if (s == 0 || samples[s].first != samples[s - 1].first) group_start.push_back(s);
  group_start.push_back(samples.size());
  const auto position = [&](std::int64_t n) {
    const std::int64_t plane = static_cast<std::int64_t>(nx) * ny;
    return grid.position(static_cast<int>(n % nx), static_cast<int>((n / nx) % ny),
                         static_cast<int>(n / plane));
  };
  reporter.progress("distance transform", 0.7);
  const std::size_t groups = group_start.size() - 1;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, groups, 64), [&](const auto& r) {
    SiteGeometry site;
    std::vector<double> sphere_distance;
    for (std::size_t g = r.begin(); g != r.end(); ++g) {
      boundary_distance.build_site(position(samples[group_start[g]].first), near_reach, site);
      for (std::size_t s = group_start[g]; s != group_start[g + 1]; ++s) {
        const std::size_t n = static_cast<std::size_t>(samples[s].second);
        const double d = boundary_distance(position(samples[s].second), site,
                                           std::sqrt(edt.squared_distance[n]), sphere_distance);
        grid.values[n] = d - probe;
      }
    }
  });
  reporter.progress("distance transform", 1.0);
  return grid;
}

}  // namespace molmesh
