#include "molmesh/hierarchy/transfer.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "molmesh/core/error.hpp"
#include "molmesh/geometry/box_index.hpp"
#include "molmesh/geometry/closest_point.hpp"
#include "molmesh/geometry/tetrahedron.hpp"

namespace molmesh {
namespace {

using Entry = std::pair<int, double>;
using Row = std::vector<Entry>;

// Weights below this are rounding noise (a fine vertex coinciding with a coarse one).
constexpr double kDropWeight = 1e-13;

Eigen::Vector4d tet_barycentric(const TetMesh& mesh, const Tetrahedron& t, const Vec3& p) {
  const auto P = [&](int k) -> const Vec3& { return mesh.points[static_cast<std::size_t>(t[k])]; };
  return molmesh::tet_barycentric(P(0), P(1), P(2), P(3), p);
}

Box3 box_of(std::span<const int> vertices, const std::vector<Vec3>& points) {
  Box3 box;
  for (int v : vertices) box.extend(points[static_cast<std::size_t>(v)]);
  // Inflate a little so points on faces are reported by the tree despite rounding.
  const double pad = 1e-9 * (box.diagonal().norm() + 1.0);
  box.min().array() -= pad;
  box.max().array() += pad;
  return box;
}

// Weights of the closest point of triangle t to p.
Row triangle_row(const std::vector<Vec3>& points, const Triangle& t, const Vec3& p) {
  const Eigen::Vector3d w = closest_point_barycentric(p, points[static_cast<std::size_t>(t[0])],
                                                      points[static_cast<std::size_t>(t[1])],
                                                      points[static_cast<std::size_t>(t[2])]);
  Row row;
  for (int k = 0; k < 3; ++k) {
    if (w[k] > kDropWeight) row.emplace_back(t[static_cast<std::size_t>(k)], w[k]);
  }
  return row;
}

double triangle_distance_sq(const std::vector<Vec3>& points, const Triangle& t, const Vec3& p) {
  const Vec3& a = points[static_cast<std::size_t>(t[0])];
  const Vec3& b = points[static_cast<std::size_t>(t[1])];
  const Vec3& c = points[static_cast<std::size_t>(t[2])];
  const Eigen::Vector3d w = closest_point_barycentric(p, a, b, c);
  return (w[0] * a + w[1] * b + w[2] * c - p).squaredNorm();
}

// Sorts by column, merges duplicates, drops noise and renormalises to an exact unit sum.
void normalise(Row& row) {
  std::sort(row.begin(), row.end());
  Row merged;
  for (const auto& [column, weight] : row) {
    if (!merged.empty() && merged.back().first == column) {
      merged.back().second += weight;
    } else {
      merged.emplace_back(column, weight);
    }
  }
  std::erase_if(merged, [](const Entry& e) { return std::abs(e.second) <= kDropWeight; });
  double sum = 0.0;
  for (const auto& e : merged) sum += e.second;
  if (sum != 0.0) {
    for (auto& e : merged) e.second /= sum;
  }
  row = std::move(merged);
}

SparseMatrix assemble(const std::vector<Row>& rows, std::size_t columns) {
  SparseMatrix matrix(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(columns));
  std::size_t nnz = 0;
  for (const auto& row : rows) nnz += row.size();
  matrix.reserve(static_cast<Eigen::Index>(nnz));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    matrix.startVec(static_cast<Eigen::Index>(i));
    for (const auto& [column, weight] : rows[i]) {
      matrix.insertBack(static_cast<Eigen::Index>(i), column) = weight;
    }
  }
  matrix.finalize();
  matrix.makeCompressed();
  return matrix;
}

std::vector<char> used_columns(const std::vector<Row>& rows, std::size_t columns) {
  std::vector<char> used(columns, 0);
  for (const auto& row : rows) {
    for (const auto& e : row) used[static_cast<std::size_t>(e.first)] = 1;
  }
  return used;
}

BoxIndex point_tree(const std::vector<Vec3>& points) {
  std::vector<Box3> boxes(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) boxes[i] = Box3(points[i], points[i]);
  return BoxIndex(boxes);
}

}  // namespace

std::vector<Triangle> tet_mesh_boundary(const TetMesh& mesh) {
  struct Face {
    std::array<int, 3> key;
    Triangle oriented;
  };
  std::vector<Face> faces;
  faces.reserve(mesh.tetrahedra.size() * 4);
  for (const auto& t : mesh.tetrahedra) {
    for (const auto& f : kTetFaces) {
      Triangle tri{t[static_cast<std::size_t>(f[0])], t[static_cast<std::size_t>(f[1])],
                   t[static_cast<std::size_t>(f[2])]};
      auto key = tri;
      std::sort(key.begin(), key.end());
      faces.push_back({key, tri});
    }
  }
  std::sort(faces.begin(), faces.end(), [](const Face& a, const Face& b) {
    return a.key < b.key || (a.key == b.key && a.oriented < b.oriented);
  });
  std::vector<Triangle> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i + 1;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i == 1) boundary.push_back(faces[i].oriented);
    i = j;
  }
  return boundary;
}

SparseMatrix volume_prolongation(const TetMesh& coarse, const TetMesh& fine, TransferStats* stats) {
  if (coarse.tetrahedra.empty())
    throw Error("volume prolongation: the coarse mesh has no tetrahedra");
  std::vector<Box3> tet_boxes(coarse.tetrahedra.size());
  tbb::parallel_for(std::size_t{0}, tet_boxes.size(), [&](std::size_t t) {
    tet_boxes[t] = box_of(coarse.tetrahedra[t], coarse.points);
  });
  const BoxIndex tets(tet_boxes);
  const auto boundary = tet_mesh_boundary(coarse);
  std::vector<Box3> face_boxes(boundary.size());
  for (std::size_t f = 0; f < boundary.size(); ++f)
    face_boxes[f] = box_of(boundary[f], coarse.points);
  const BoxIndex faces(face_boxes);

  const std::size_t n = fine.points.size();
  std::vector<Row> rows(n);
  std::vector<int> row_tet(n, -1);  // tetrahedron each row came from; -1: boundary projection
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const Vec3& p = fine.points[i];
      int best = -1;
      double best_score = -std::numeric_limits<double>::infinity();
      Eigen::Vector4d best_lambda;
      tets.containing(p, [&](int t) {
        const auto lambda =
            tet_barycentric(coarse, coarse.tetrahedra[static_cast<std::size_t>(t)], p);
        const double score = lambda.minCoeff();
        if (score > best_score || (score == best_score && t < best)) {
          best_score = score;
          best = t;
          best_lambda = lambda;
        }
      });
      if (best >= 0 && best_score >= -kInsideTolerance) {
        const auto& t = coarse.tetrahedra[static_cast<std::size_t>(best)];
        Row row;
        for (int k = 0; k < 4; ++k) {
          row.emplace_back(t[static_cast<std::size_t>(k)], std::max(0.0, best_lambda[k]));
        }
        normalise(row);
        rows[i] = std::move(row);
        row_tet[i] = best;
      } else {
        const int f = faces.nearest(p, [&](int face) {
          return triangle_distance_sq(coarse.points, boundary[static_cast<std::size_t>(face)], p);
        });
        rows[i] = triangle_row(coarse.points, boundary[static_cast<std::size_t>(f)], p);
        normalise(rows[i]);
      }
    }
  });

  TransferStats local;
  for (int t : row_tet) local.fine_outside += t < 0 ? 1 : 0;

  // Repair empty columns (see transfer.hpp). Sequential and in vertex order: deterministic.
  const auto used = used_columns(rows, coarse.points.size());
  const BoxIndex fine_points = point_tree(fine.points);
  for (std::size_t c = 0; c < used.size(); ++c) {
    if (used[c]) continue;
    const Vec3& xc = coarse.points[c];
    const int ci = static_cast<int>(c);
    const auto eligible = [&](int f) {
      const int t = row_tet[static_cast<std::size_t>(f)];
      if (t < 0) return false;
      const auto& tet = coarse.tetrahedra[static_cast<std::size_t>(t)];
      return std::find(tet.begin(), tet.end(), ci) == tet.end();
    };
    const int f = fine_points.nearest(xc, [&](int v) {
      return eligible(v) ? (fine.points[static_cast<std::size_t>(v)] - xc).squaredNorm()
                         : std::numeric_limits<double>::infinity();
    });
    if (f < 0) {
      // No fine vertex lies in a tetrahedron: blend the nearest one (loses exactness there).
      const int g = fine_points.nearest(
          xc, [&](int v) { return (fine.points[static_cast<std::size_t>(v)] - xc).squaredNorm(); });
      auto& row = rows[static_cast<std::size_t>(g)];
      for (auto& e : row) e.second *= 0.5;
      row.emplace_back(ci, 0.5);
      normalise(row);
      ++local.empty_columns_repaired;
      continue;
    }
    auto& row = rows[static_cast<std::size_t>(f)];
    const auto& tet =
        coarse.tetrahedra[static_cast<std::size_t>(row_tet[static_cast<std::size_t>(f)])];
    const auto lambda = tet_barycentric(coarse, tet, xc);
    // Largest step (up to injection, t = 1) that keeps the tetrahedron's weights >= 0; a
    // floor keeps the new column meaningful when the fine vertex sits on a face (its weights
    // may then go slightly negative, which keeps exactness).
    double step = 1.0;
    for (int k = 0; k < 4; ++k) {
      if (lambda[k] <= 0) continue;
      double current = 0.0;
      for (const auto& e : row) {
        if (e.first == tet[static_cast<std::size_t>(k)]) current = e.second;
      }
      step = std::min(step, current / lambda[k]);
    }
    // Half of that step, so no existing entry is driven to zero (it may be the only entry of
    // another column).
    step = std::max(0.5 * step, 0.05);
    for (int k = 0; k < 4; ++k)
      row.emplace_back(tet[static_cast<std::size_t>(k)], -step * lambda[k]);
    row.emplace_back(ci, step);
    // Merge without dropping: the new entries cancel exactly what the moment condition needs.
    normalise(row);
    ++local.empty_columns_repaired;
  }
  if (stats) *stats = local;
  return assemble(rows, coarse.points.size());
}

SparseMatrix surface_prolongation(const SurfaceMesh& coarse, const SurfaceMesh& fine,
                                  std::span<const int> provenance, TransferStats* stats) {
  if (coarse.triangles.empty()) throw Error("surface prolongation: the coarse surface is empty");
  const std::size_t n = fine.points.size();
  std::vector<Row> rows(n);
  std::vector<char> identity(n, 0);
  if (provenance.size() == coarse.points.size()) {
    for (std::size_t c = 0; c < provenance.size(); ++c) {
      const int f = provenance[c];
      if (f < 0 || static_cast<std::size_t>(f) >= n || identity[static_cast<std::size_t>(f)])
        continue;
      identity[static_cast<std::size_t>(f)] = 1;
      rows[static_cast<std::size_t>(f)] = {{static_cast<int>(c), 1.0}};
    }
  }
  std::vector<Box3> boxes(coarse.triangles.size());
  for (std::size_t t = 0; t < boxes.size(); ++t)
    boxes[t] = box_of(coarse.triangles[t], coarse.points);
  const BoxIndex triangles(boxes);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 256), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      if (identity[i]) continue;
      const Vec3& p = fine.points[i];
      const int t = triangles.nearest(p, [&](int tri) {
        return triangle_distance_sq(coarse.points, coarse.triangles[static_cast<std::size_t>(tri)],
                                    p);
      });
      rows[i] = triangle_row(coarse.points, coarse.triangles[static_cast<std::size_t>(t)], p);
      normalise(rows[i]);
    }
  });
  TransferStats local;
  const auto used = used_columns(rows, coarse.points.size());
  const BoxIndex fine_points = point_tree(fine.points);
  for (std::size_t c = 0; c < used.size(); ++c) {
    if (used[c]) continue;
    const Vec3& xc = coarse.points[c];
    int f = fine_points.nearest(xc, [&](int v) {
      return identity[static_cast<std::size_t>(v)]
                 ? std::numeric_limits<double>::infinity()
                 : (fine.points[static_cast<std::size_t>(v)] - xc).squaredNorm();
    });
    if (f < 0)
      f = fine_points.nearest(
          xc, [&](int v) { return (fine.points[static_cast<std::size_t>(v)] - xc).squaredNorm(); });
    auto& row = rows[static_cast<std::size_t>(f)];
    for (auto& e : row) e.second *= 0.5;
    row.emplace_back(static_cast<int>(c), 0.5);
    normalise(row);
    ++local.empty_columns_repaired;
  }
  if (stats) *stats = local;
  return assemble(rows, coarse.points.size());
}

}  // namespace molmesh
