#include "solvers/fem/p1_assembly.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "molmesh/core/error.hpp"

namespace molmesh::solvers {

TetGeometry tet_geometry(const TetMesh& mesh, std::size_t t) {
  const Tetrahedron& tet = mesh.tetrahedra[t];
  const Vec3& p0 = mesh.points[static_cast<std::size_t>(tet[0])];
  const Vec3 e1 = mesh.points[static_cast<std::size_t>(tet[1])] - p0;
  const Vec3 e2 = mesh.points[static_cast<std::size_t>(tet[2])] - p0;
  const Vec3 e3 = mesh.points[static_cast<std::size_t>(tet[3])] - p0;
  const double det = e1.dot(e2.cross(e3));
  TetGeometry g;
  g.volume = det / 6.0;
  // Rows of the inverse Jacobian are the gradients of barycentric coordinates 1..3.
  g.gradients[1] = e2.cross(e3) / det;
  g.gradients[2] = e3.cross(e1) / det;
  g.gradients[3] = e1.cross(e2) / det;
  g.gradients[0] = -(g.gradients[1] + g.gradients[2] + g.gradients[3]);
  return g;
}

namespace {

// The cells around every vertex, in CSR form, cells in increasing order.
struct VertexCells {
  std::vector<int> start;
  std::vector<int> cell;
};

VertexCells vertex_cells(const TetMesh& mesh) {
  VertexCells vc;
  const std::size_t nv = mesh.points.size();
  vc.start.assign(nv + 1, 0);
  for (const Tetrahedron& tet : mesh.tetrahedra) {
    for (int v : tet) {
      if (v < 0 || static_cast<std::size_t>(v) >= nv) {
        throw Error("stiffness assembly: a tetrahedron refers to vertex " + std::to_string(v) +
                    " of a mesh with " + std::to_string(nv) + " vertices");
      }
      ++vc.start[static_cast<std::size_t>(v) + 1];
    }
  }
  for (std::size_t v = 0; v < nv; ++v) vc.start[v + 1] += vc.start[v];
  vc.cell.resize(static_cast<std::size_t>(vc.start.back()));
  std::vector<int> next(vc.start.begin(), vc.start.end() - 1);
  for (std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    for (int v : mesh.tetrahedra[t])
      vc.cell[static_cast<std::size_t>(next[static_cast<std::size_t>(v)]++)] = static_cast<int>(t);
  }
  return vc;
}

// One thread's scratch space for gathering rows: for every vertex, the row that last saw
// it and its place in that row's value array; the first bad cell this thread met.
struct RowGatherer {
  std::vector<int> seen_in_row;
  std::vector<int> place;
  std::vector<int> columns;
  std::size_t first_bad_cell = std::numeric_limits<std::size_t>::max();

  explicit RowGatherer(std::size_t nv) : seen_in_row(nv, -1), place(nv, 0) {}

  // The vertices of the cells around v, each once, unsorted.
  void gather(const TetMesh& mesh, const VertexCells& around, std::size_t v) {
    columns.clear();
    for (int k = around.start[v]; k < around.start[v + 1]; ++k) {
      const auto t = static_cast<std::size_t>(around.cell[static_cast<std::size_t>(k)]);
      for (int u : mesh.tetrahedra[t]) {
        if (seen_in_row[static_cast<std::size_t>(u)] != static_cast<int>(v)) {
          seen_in_row[static_cast<std::size_t>(u)] = static_cast<int>(v);
          columns.push_back(u);
        }
      }
    }
  }
};

// Row `v` of one cell's stiffness up to the factor k/(6 det): n_a . n_b for every vertex b
// of the cell, where n_b = det * grad(phi_b) is the (inward, unnormalised) normal of the
// face opposite b and a is v's place in the cell. K_ab = k |T| g_a.g_b = k n_a.n_b / (6 det),
// so one division per cell visit (tet_geometry's gradients need nine).
struct StiffnessRow {
  std::array<double, 4> dots;
  double det = 0.0;  // 6 |T|, signed
};

StiffnessRow stiffness_row(const TetMesh& mesh, const Tetrahedron& tet, std::size_t v) {
  const Vec3& p0 = mesh.points[static_cast<std::size_t>(tet[0])];
  const Vec3 e1 = mesh.points[static_cast<std::size_t>(tet[1])] - p0;
  const Vec3 e2 = mesh.points[static_cast<std::size_t>(tet[2])] - p0;
  const Vec3 e3 = mesh.points[static_cast<std::size_t>(tet[3])] - p0;
  std::array<Vec3, 4> n;
  n[1] = e2.cross(e3);
  n[2] = e3.cross(e1);
  n[3] = e1.cross(e2);
  n[0] = -(n[1] + n[2] + n[3]);
  std::size_t a = 0;  // v's place in the cell
  while (a < 3 && static_cast<std::size_t>(tet[a]) != v) ++a;
  StiffnessRow row;
  row.det = e1.dot(n[1]);
  for (std::size_t b = 0; b < 4; ++b) row.dots[b] = n[a].dot(n[b]);
  return row;
}

}  // namespace

SparseMatrix assemble_stiffness(const TetMesh& mesh, std::span<const double> cell_coefficient,
                                std::span<const int> kept_index) {
  const std::size_t nt = mesh.tetrahedra.size();
  const std::size_t nv = mesh.points.size();
  if (cell_coefficient.size() != nt) {
    throw Error("stiffness assembly: " + std::to_string(cell_coefficient.size()) +
                " coefficients for " + std::to_string(nt) + " tetrahedra");
  }
  const bool keeps_all = kept_index.empty();
  int kept = keeps_all ? static_cast<int>(nv) : 0;
  if (!keeps_all) {
    if (kept_index.size() != nv) {
      throw Error("stiffness assembly: " + std::to_string(kept_index.size()) +
                  " kept-vertex indices for " + std::to_string(nv) + " vertices");
    }
    // Kept vertices numbered 0, 1, 2, ... in vertex order, so sorted vertex columns stay
    // sorted after renumbering.
    for (int index : kept_index) {
      if (index < 0) continue;
      if (index != kept) {
        throw Error("stiffness assembly: kept vertices must be numbered in vertex order");
      }
      ++kept;
    }
  }
  auto index_of = [&](std::size_t v) { return keeps_all ? static_cast<int>(v) : kept_index[v]; };
  const VertexCells around = vertex_cells(mesh);
  // Every row gathers its entries from the cells around its vertex. Rows are independent,
  // so they are built in parallel without atomics, and each entry is summed in increasing
  // cell order: the matrix does not depend on the thread count. A cell's geometry is
  // recomputed for each of its four rows rather than stored: the flops are cheaper than
  // writing and re-reading 80 bytes per cell (and, in a fresh process, than faulting in
  // those pages). (A triplet list through setFromTriplets, the obvious alternative, moved
  // 16 triplets per cell through memory several times and was 5-10x slower.)
  tbb::enumerable_thread_specific<RowGatherer> gatherers([nv] { return RowGatherer(nv); });
  constexpr std::size_t kGrain = 1024;
  SparseMatrix k(kept, kept);
  int* outer = k.outerIndexPtr();
  // Runs row_body(gatherer, v, row) for every kept vertex v, its cells' vertices gathered.
  auto for_each_kept_row = [&](auto&& row_body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv, kGrain),
                      [&](const tbb::blocked_range<std::size_t>& rows) {
                        RowGatherer& g = gatherers.local();
                        for (std::size_t v = rows.begin(); v != rows.end(); ++v) {
                          const int row = index_of(v);
                          if (row < 0) continue;
                          g.gather(mesh, around, v);
                          row_body(g, v, row);
                        }
                      });
  };
  for_each_kept_row([&](RowGatherer& g, std::size_t, int row) {
    int count = 0;
    for (int u : g.columns) count += index_of(static_cast<std::size_t>(u)) >= 0;
    outer[row + 1] = count;
  });
  outer[0] = 0;
  for (int r = 0; r < kept; ++r) outer[r + 1] += outer[r];
  k.resizeNonZeros(outer[kept]);
  int* inner = k.innerIndexPtr();
  double* values = k.valuePtr();
  // The second pass gathers again: seen_in_row must forget the first.
  for (RowGatherer& g : gatherers) std::fill(g.seen_in_row.begin(), g.seen_in_row.end(), -1);
  for_each_kept_row([&](RowGatherer& g, std::size_t v, int row) {
    std::sort(g.columns.begin(), g.columns.end());
    auto next = static_cast<std::size_t>(outer[row]);
    for (int u : g.columns) {
      const auto uu = static_cast<std::size_t>(u);
      const int column = index_of(uu);
      if (column < 0) {
        g.place[uu] = -1;
        continue;
      }
      inner[next] = column;
      values[next] = 0.0;
      g.place[uu] = static_cast<int>(next++);
    }
    for (int c = around.start[v]; c < around.start[v + 1]; ++c) {
      const auto t = static_cast<std::size_t>(around.cell[static_cast<std::size_t>(c)]);
      const Tetrahedron& tet = mesh.tetrahedra[t];
      const StiffnessRow entries = stiffness_row(mesh, tet, v);
      if (!(entries.det > 0.0) || !std::isfinite(entries.det))
        g.first_bad_cell = std::min(g.first_bad_cell, t);
      const double scale = cell_coefficient[t] / (6.0 * entries.det);
      for (std::size_t b = 0; b < 4; ++b) {
        const int place = g.place[static_cast<std::size_t>(tet[b])];
        if (place >= 0) values[place] += scale * entries.dots[b];
      }
    }
  });
  std::size_t first_bad_cell = std::numeric_limits<std::size_t>::max();
  for (const RowGatherer& g : gatherers)
    first_bad_cell = std::min(first_bad_cell, g.first_bad_cell);
  if (first_bad_cell < nt) {
    throw Error("stiffness assembly: tetrahedron " + std::to_string(first_bad_cell) +
                " is inverted or degenerate (non-positive volume); the mesh cannot be used "
                "for finite elements");
  }
  return k;
}

std::vector<double> cell_coefficients_by_region(const TetMesh& mesh,
                                                std::span<const std::pair<int, double>> regions) {
  std::vector<double> out(mesh.tetrahedra.size());
  for (std::size_t t = 0; t < out.size(); ++t) {
    const int marker = t < mesh.cell_markers.size() ? mesh.cell_markers[t] : 0;
    bool found = false;
    for (const auto& [m, value] : regions) {
      if (m == marker) {
        out[t] = value;
        found = true;
        break;
      }
    }
    if (!found) {
      throw Error("tetrahedron " + std::to_string(t) + " has region marker " +
                  std::to_string(marker) + ", which has no coefficient");
    }
  }
  return out;
}

}  // namespace molmesh::solvers
