#include "solvers/fem/p1_assembly.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
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

// Index of entry (a, b), a <= b, among a tetrahedron's 10 distinct local entries.
int local_entry(int a, int b) {
  static constexpr int kIndex[4][4] = {{0, 1, 2, 3}, {1, 4, 5, 6}, {2, 5, 7, 8}, {3, 6, 8, 9}};
  return kIndex[a][b];
}

// One thread's scratch space for gathering rows: for every vertex, the row that last saw
// it and its place in that row.
struct RowGatherer {
  std::vector<int> seen_in_row;
  std::vector<int> place;
  std::vector<int> columns;

  explicit RowGatherer(std::size_t nv) : seen_in_row(nv, -1), place(nv, 0) {}
};

// Rows first..last-1 of the matrix, built by one task: its part of the column indices and
// values, and each row's length.
struct RowChunk {
  std::vector<int> length;
  std::vector<int> inner;
  std::vector<double> values;
};

}  // namespace

SparseMatrix assemble_stiffness(const TetMesh& mesh, std::span<const double> cell_coefficient) {
  const std::size_t nt = mesh.tetrahedra.size();
  if (cell_coefficient.size() != nt) {
    throw Error("stiffness assembly: " + std::to_string(cell_coefficient.size()) +
                " coefficients for " + std::to_string(nt) + " tetrahedra");
  }
  const VertexCells around = vertex_cells(mesh);
  // The local matrices first (each cell once); then every row gathers its entries from
  // the cells around its vertex. Rows are independent, so they are built in parallel
  // without atomics, and each entry is summed in increasing cell order: the matrix does
  // not depend on the thread count. (A triplet list through setFromTriplets, the obvious
  // alternative, moves 16 triplets per cell through memory several times.)
  std::vector<std::array<double, 10>> local(nt);
  std::vector<char> bad(nt, 0);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nt, 4096),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t t = range.begin(); t != range.end(); ++t) {
                        const TetGeometry g = tet_geometry(mesh, t);
                        if (!(g.volume > 0.0) || !std::isfinite(g.volume)) bad[t] = 1;
                        const double w = cell_coefficient[t] * g.volume;
                        for (int a = 0; a < 4; ++a) {
                          for (int b = a; b < 4; ++b) {
                            local[t][static_cast<std::size_t>(local_entry(a, b))] =
                                w * g.gradients[static_cast<std::size_t>(a)].dot(
                                        g.gradients[static_cast<std::size_t>(b)]);
                          }
                        }
                      }
                    });
  for (std::size_t t = 0; t < nt; ++t) {
    if (bad[t]) {
      throw Error("stiffness assembly: tetrahedron " + std::to_string(t) +
                  " is inverted or degenerate (non-positive volume); the mesh cannot be used "
                  "for finite elements");
    }
  }

  // Every row in one pass: its columns (the vertices of the cells around it, each once,
  // sorted) and its values. Rows go in fixed chunks so the chunks can be laid end to end
  // once all lengths are known.
  const std::size_t nv = mesh.points.size();
  tbb::enumerable_thread_specific<RowGatherer> gatherers([nv] { return RowGatherer(nv); });
  constexpr std::size_t kChunk = 1024;
  std::vector<RowChunk> chunks((nv + kChunk - 1) / kChunk);
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    RowGatherer& g = gatherers.local();
    RowChunk& chunk = chunks[c];
    const std::size_t first = c * kChunk;
    const std::size_t last = std::min(nv, first + kChunk);
    chunk.length.reserve(last - first);
    for (std::size_t v = first; v < last; ++v) {
      g.columns.clear();
      for (int k = around.start[v]; k < around.start[v + 1]; ++k) {
        const auto t = static_cast<std::size_t>(around.cell[static_cast<std::size_t>(k)]);
        for (int u : mesh.tetrahedra[t]) {
          if (g.seen_in_row[static_cast<std::size_t>(u)] != static_cast<int>(v)) {
            g.seen_in_row[static_cast<std::size_t>(u)] = static_cast<int>(v);
            g.columns.push_back(u);
          }
        }
      }
      std::sort(g.columns.begin(), g.columns.end());
      const std::size_t row_start = chunk.inner.size();
      for (std::size_t k = 0; k < g.columns.size(); ++k)
        g.place[static_cast<std::size_t>(g.columns[k])] = static_cast<int>(row_start + k);
      chunk.inner.insert(chunk.inner.end(), g.columns.begin(), g.columns.end());
      chunk.values.resize(chunk.inner.size(), 0.0);
      chunk.length.push_back(static_cast<int>(g.columns.size()));
      for (int k = around.start[v]; k < around.start[v + 1]; ++k) {
        const auto t = static_cast<std::size_t>(around.cell[static_cast<std::size_t>(k)]);
        const Tetrahedron& tet = mesh.tetrahedra[t];
        int a = 0;  // v's place in the cell
        while (a < 3 && static_cast<std::size_t>(tet[static_cast<std::size_t>(a)]) != v) ++a;
        for (int b = 0; b < 4; ++b) {
          const auto u = static_cast<std::size_t>(tet[static_cast<std::size_t>(b)]);
          chunk.values[static_cast<std::size_t>(g.place[u])] +=
              local[t][static_cast<std::size_t>(a <= b ? local_entry(a, b) : local_entry(b, a))];
        }
      }
    }
  });
  std::vector<int> outer(nv + 1, 0);
  std::vector<std::size_t> chunk_start(chunks.size() + 1, 0);
  for (std::size_t c = 0; c < chunks.size(); ++c) {
    chunk_start[c + 1] = chunk_start[c] + chunks[c].inner.size();
    for (std::size_t r = 0; r < chunks[c].length.size(); ++r) {
      const std::size_t v = c * kChunk + r;
      outer[v + 1] = outer[v] + chunks[c].length[r];
    }
  }
  const std::size_t nnz = chunk_start.back();
  std::vector<int> inner(nnz);
  std::vector<double> values(nnz);
  tbb::parallel_for(std::size_t{0}, chunks.size(), [&](std::size_t c) {
    std::copy(chunks[c].inner.begin(), chunks[c].inner.end(),
              inner.begin() + static_cast<std::ptrdiff_t>(chunk_start[c]));
    std::copy(chunks[c].values.begin(), chunks[c].values.end(),
              values.begin() + static_cast<std::ptrdiff_t>(chunk_start[c]));
  });
  const auto n = static_cast<Eigen::Index>(nv);
  return SparseMatrix(Eigen::Map<const SparseMatrix>(n, n, static_cast<Eigen::Index>(nnz),
                                                     outer.data(), inner.data(), values.data()));
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
