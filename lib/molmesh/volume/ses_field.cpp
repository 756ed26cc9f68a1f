#include "molmesh/volume/ses_field.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <limits>

#include "molmesh/volume/ball_union.hpp"
#include "molmesh/volume/distance_transform.hpp"

namespace molmesh {
namespace {

struct Ball {
  Vec3 c;
  double R;
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

constexpr double kBuriedTolerance = 1e-7;  // Å: a point this close to a sphere is on it

struct Candidate {
  double distance;
  Vec3 point;
  int i, j, k;  // the balls it lies on (-1: none)
};

// Exact distance from x (inside the SAS) to the SAS boundary, among the boundary's critical
// points for x built from the balls `near` (sphere points, the nearest point of pairwise
// intersection circles, triple intersection points). Only points closer than `best` are
// considered; returns the smallest distance found (or `best`).
class BoundaryDistance {
 public:
  BoundaryDistance(const BallCells& cells, double max_radius)
      : cells_(cells), max_radius_(max_radius) {}

  // The exposed triple intersection points (SAS vertices) of the balls `near`: they do not
  // depend on x, so they are found once per site.
  std::vector<Vec3> exposed_vertices(const std::vector<int>& near) const {
    std::vector<Vec3> vertices;
    const std::size_t n = near.size();
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b) {
        const Ball& A = cells_.ball(near[a]);
        const Ball& B = cells_.ball(near[b]);
        if ((A.c - B.c).norm() >= A.R + B.R) continue;
        for (std::size_t c = b + 1; c < n; ++c) {
          Vec3 p1, p2;
          if (!triple(A, B, cells_.ball(near[c]), p1, p2)) continue;
          for (const Vec3& p : {p1, p2})
            if (exposed(p, near[a], near[b], near[c])) vertices.push_back(p);
        }
      }
    return vertices;
  }

  // The nearest exposed vertex, then every sphere and circle point closer than that (cheap
  // geometry; a circle point of (a, b) lies on sphere a, which bounds it from below), tested
  // for exposure nearest first: the first exposed one is the answer.
  double operator()(const Vec3& x, const int* near, std::size_t n,
                    const std::vector<Vec3>& vertices, double best,
                    std::vector<Candidate>& candidates) const {
    for (const Vec3& v : vertices) best = std::min(best, (x - v).norm());
    candidates.clear();
    for (std::size_t a = 0; a < n; ++a) {
      const Ball& A = cells_.ball(near[a]);
      const Vec3 w = x - A.c;
      const double len = w.norm();
      const double da = std::abs(A.R - len);
      if (da >= best) continue;
      if (len > 0.0) candidates.push_back({da, A.c + w * (A.R / len), near[a], -1, -1});
      for (std::size_t b = a + 1; b < n; ++b) {
        const Ball& B = cells_.ball(near[b]);
        Vec3 m, axis;
        double rho;
        if (!circle(A, B, m, axis, rho)) continue;
        Vec3 u = x - m;
        u -= u.dot(axis) * axis;
        const double ul = u.norm();
        if (ul < 1e-12)
          u = axis.unitOrthogonal();
        else
          u /= ul;
        const Vec3 q = m + rho * u;
        const double d = (x - q).norm();
        if (d >= best) continue;
        candidates.push_back({d, q, near[a], near[b], -1});
      }
    }
    std::sort(candidates.begin(), candidates.end(),
              [](const Candidate& l, const Candidate& r) { return l.distance < r.distance; });
    // The balls near the site bury most candidates, so they are tried before the full scan.
    auto buried_by_near = [&](const Candidate& c) {
      for (std::size_t b = 0; b < n; ++b) {
        if (near[b] == c.i || near[b] == c.j) continue;
        const Ball& B = cells_.ball(near[b]);
        const double r = B.R - kBuriedTolerance;
        if ((c.point - B.c).squaredNorm() < r * r) return true;
      }
      return false;
    };
    for (const Candidate& c : candidates)
      if (!buried_by_near(c) && exposed(c.point, c.i, c.j, c.k)) return c.distance;
    return best;
  }

 private:
  bool exposed(const Vec3& q, int i, int j, int k) const {
    return cells_.for_each_near(q, max_radius_, [&](int b) {
      if (b == i || b == j || b == k) return true;
      const Ball& B = cells_.ball(b);
      const double r = B.R - kBuriedTolerance;
      return (q - B.c).squaredNorm() >= r * r;
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
    balls.push_back({atom.center, atom.radius + probe});
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
  std::vector<std::int64_t> samples;
  for (const auto& plane : band) samples.insert(samples.end(), plane.begin(), plane.end());
  band.clear();
  // The balls passing by each distinct site, once per site (compressed rows).
  std::vector<std::int64_t> sites(samples.size());
  for (std::size_t s = 0; s < samples.size(); ++s) sites[s] = edt.nearest[std::size_t(samples[s])];
  std::sort(sites.begin(), sites.end());
  sites.erase(std::unique(sites.begin(), sites.end()), sites.end());
  std::vector<std::vector<int>> site_balls(sites.size());
  std::vector<std::vector<Vec3>> site_vertices(sites.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, sites.size(), 256), [&](const auto& r) {
    for (std::size_t s = r.begin(); s != r.end(); ++s) {
      const std::int64_t n = sites[s];
      const Vec3 site = grid.position(static_cast<int>(n % nx), static_cast<int>((n / nx) % ny),
                                      static_cast<int>(n / (static_cast<std::int64_t>(nx) * ny)));
      cells.for_each_near(site, max_radius + near_reach, [&](int b) {
        const Ball& B = cells.ball(b);
        if (std::abs((site - B.c).norm() - B.R) <= near_reach) site_balls[s].push_back(b);
        return true;
      });
      site_vertices[s] = boundary_distance.exposed_vertices(site_balls[s]);
    }
  });
  reporter.progress("distance transform", 0.7);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, samples.size(), 512), [&](const auto& r) {
    std::vector<Candidate> candidates;
    for (std::size_t s = r.begin(); s != r.end(); ++s) {
      const std::size_t n = static_cast<std::size_t>(samples[s]);
      const std::size_t slot = static_cast<std::size_t>(
          std::lower_bound(sites.begin(), sites.end(), edt.nearest[n]) - sites.begin());
      const std::vector<int>& near = site_balls[slot];
      const int i = static_cast<int>(n % std::size_t(nx));
      const int j = static_cast<int>((n / std::size_t(nx)) % std::size_t(ny));
      const int k = static_cast<int>(n / (std::size_t(nx) * std::size_t(ny)));
      const double d =
          boundary_distance(grid.position(i, j, k), near.data(), near.size(), site_vertices[slot],
                            std::sqrt(edt.squared_distance[n]), candidates);
      grid.values[n] = d - probe;
    }
  });
  reporter.progress("distance transform", 1.0);
  return grid;
}

}  // namespace molmesh
