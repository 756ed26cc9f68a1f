#include "solvers/multigrid/aggregation.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace molmesh::solvers {
namespace {

// Strong neighbours of every unknown, in CSR form.
struct StrongGraph {
  std::vector<int> start;
  std::vector<int> neighbour;
  std::vector<double> weight;  // |a_ij| / sqrt(a_ii a_jj)
};

StrongGraph strong_graph(const SparseMatrix& a, const Eigen::VectorXd& diagonal, double theta) {
  StrongGraph g;
  const auto n = a.rows();
  g.start.reserve(static_cast<std::size_t>(n) + 1);
  // Upper bounds: reserved pages that are never written are never touched.
  g.neighbour.reserve(static_cast<std::size_t>(a.nonZeros()));
  g.weight.reserve(static_cast<std::size_t>(a.nonZeros()));
  g.start.push_back(0);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (SparseMatrix::InnerIterator it(a, i); it; ++it) {
      const Eigen::Index j = it.col();
      if (j == i) continue;
      const double w = std::abs(it.value()) / std::sqrt(diagonal[i] * diagonal[j]);
      if (w >= theta) {
        g.neighbour.push_back(static_cast<int>(j));
        g.weight.push_back(w);
      }
    }
    g.start.push_back(static_cast<int>(g.neighbour.size()));
  }
  return g;
}

// The three classic passes: disjoint neighbourhoods as seeds, leftovers joined to their
// strongest aggregated neighbour, what remains aggregated with its free neighbours.
// Unknowns without strong neighbours stay unaggregated (-1): smoothing alone resolves them.
std::vector<int> aggregate(const StrongGraph& g, int& count) {
  const int n = static_cast<int>(g.start.size()) - 1;
  std::vector<int> agg(static_cast<std::size_t>(n), -1);
  count = 0;
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0 || g.start[i] == g.start[i + 1]) continue;
    bool all_free = true;
    for (int k = g.start[i]; k < g.start[i + 1] && all_free; ++k)
      all_free = agg[g.neighbour[k]] < 0;
    if (!all_free) continue;
    agg[i] = count;
    for (int k = g.start[i]; k < g.start[i + 1]; ++k) agg[g.neighbour[k]] = count;
    ++count;
  }
  // Joining uses the seeds' assignment only, so aggregates do not grow into chains.
  std::vector<int> joined = agg;
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0) continue;
    double best = 0.0;
    for (int k = g.start[i]; k < g.start[i + 1]; ++k) {
      const int j = g.neighbour[k];
      if (agg[j] >= 0 && g.weight[k] > best) {
        best = g.weight[k];
        joined[i] = agg[j];
      }
    }
  }
  agg = std::move(joined);
  for (int i = 0; i < n; ++i) {
    if (agg[i] >= 0 || g.start[i] == g.start[i + 1]) continue;
    agg[i] = count;
    for (int k = g.start[i]; k < g.start[i + 1]; ++k)
      if (agg[g.neighbour[k]] < 0) agg[g.neighbour[k]] = count;
    ++count;
  }
  return agg;
}

// Gershgorin bound on the spectral radius of D^-1 A: an upper bound, so ω never exceeds
// the value that keeps the prolongation smoother stable.
double spectral_radius_bound(const SparseMatrix& a, const Eigen::VectorXd& diagonal) {
  double bound = 0.0;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    double row = 0.0;
    for (SparseMatrix::InnerIterator it(a, i); it; ++it) row += std::abs(it.value());
    bound = std::max(bound, row / diagonal[i]);
  }
  return bound;
}

}  // namespace

SparseMatrix smoothed_aggregation_prolongation(const SparseMatrix& a,
                                               const AggregationOptions& options) {
  const Eigen::VectorXd diagonal = a.diagonal();
  const StrongGraph graph = strong_graph(a, diagonal, options.strength_threshold);
  int aggregates = 0;
  const std::vector<int> agg = aggregate(graph, aggregates);
  SparseMatrix p(a.rows(), aggregates);
  if (aggregates == 0) return p;

  const double omega = options.relaxation / spectral_radius_bound(a, diagonal);
  // Row i of (I - ω D^-1 A) T: T's 1 at agg(i), minus ω a_ij / a_ii at agg(j) for every j.
  // Written row by row straight into p (a row has at most 1 + nnz(A row i) entries).
  p.resizeNonZeros(a.nonZeros() + a.rows());
  int* outer = p.outerIndexPtr();
  int count = 0;
  outer[0] = 0;
  std::vector<double> row_value(static_cast<std::size_t>(aggregates), 0.0);
  std::vector<Eigen::Index> row_of_value(static_cast<std::size_t>(aggregates), -1);
  std::vector<int> row_columns;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    row_columns.clear();
    auto add = [&](int column, double value) {
      if (row_of_value[column] != i) {
        row_of_value[column] = i;
        row_value[column] = 0.0;
        row_columns.push_back(column);
      }
      row_value[column] += value;
    };
    if (agg[i] >= 0) add(agg[i], 1.0);
    for (SparseMatrix::InnerIterator it(a, i); it; ++it) {
      const int column = agg[it.col()];
      if (column >= 0) add(column, -omega * it.value() / diagonal[i]);
    }
    std::sort(row_columns.begin(), row_columns.end());
    for (int column : row_columns) {
      if (row_value[column] != 0.0) {
        p.innerIndexPtr()[count] = column;
        p.valuePtr()[count] = row_value[column];
        ++count;
      }
    }
    outer[i + 1] = count;
  }
  p.resizeNonZeros(count);
  return p;
}

}  // namespace molmesh::solvers
