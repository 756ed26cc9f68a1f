#include "solvers/multigrid/sparse_product.hpp"

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <vector>

#include "molmesh/core/error.hpp"

namespace molmesh::solvers {
namespace {

// One thread's dense accumulator over the result's columns.
struct RowAccumulator {
  std::vector<double> value;
  std::vector<std::size_t> stamp_of;  // the gather that last touched the column
  std::size_t stamp = 0;
  std::vector<int> columns;  // columns touched by the current gather

  explicit RowAccumulator(Eigen::Index cols)
      : value(static_cast<std::size_t>(cols), 0.0), stamp_of(static_cast<std::size_t>(cols), 0) {}

  // Gathers row i of a*b into `columns` (sorted) and `value`.
  void gather(const SparseMatrix& a, const SparseMatrix& b, Eigen::Index i) {
    columns.clear();
    ++stamp;
    for (SparseMatrix::InnerIterator ia(a, i); ia; ++ia) {
      const double aik = ia.value();
      for (SparseMatrix::InnerIterator ib(b, ia.col()); ib; ++ib) {
        const auto j = static_cast<std::size_t>(ib.col());
        if (stamp_of[j] != stamp) {
          stamp_of[j] = stamp;
          value[j] = 0.0;
          columns.push_back(static_cast<int>(j));
        }
        value[j] += aik * ib.value();
      }
    }
    std::sort(columns.begin(), columns.end());
  }
};

}  // namespace

SparseMatrix multiply(const SparseMatrix& a, const SparseMatrix& b) {
  if (a.cols() != b.rows()) throw Error("sparse product: inner dimensions differ");
  const Eigen::Index rows = a.rows();
  const Eigen::Index cols = b.cols();
  tbb::enumerable_thread_specific<RowAccumulator> accumulators(
      [cols] { return RowAccumulator(cols); });
  constexpr Eigen::Index kGrain = 1024;

  std::vector<int> outer(static_cast<std::size_t>(rows) + 1, 0);
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, rows, kGrain),
                    [&](const tbb::blocked_range<Eigen::Index>& range) {
                      RowAccumulator& acc = accumulators.local();
                      for (Eigen::Index i = range.begin(); i != range.end(); ++i) {
                        acc.gather(a, b, i);
                        outer[static_cast<std::size_t>(i) + 1] =
                            static_cast<int>(acc.columns.size());
                      }
                    });
  for (std::size_t i = 0; i < static_cast<std::size_t>(rows); ++i) outer[i + 1] += outer[i];

  const auto nnz = static_cast<std::size_t>(outer.back());
  std::vector<int> inner(nnz);
  std::vector<double> values(nnz);
  // The second pass repeats the gathering: cheaper than keeping every row's pattern.
  tbb::parallel_for(tbb::blocked_range<Eigen::Index>(0, rows, kGrain),
                    [&](const tbb::blocked_range<Eigen::Index>& range) {
                      RowAccumulator& acc = accumulators.local();
                      for (Eigen::Index i = range.begin(); i != range.end(); ++i) {
                        acc.gather(a, b, i);
                        auto k = static_cast<std::size_t>(outer[static_cast<std::size_t>(i)]);
                        for (int j : acc.columns) {
                          inner[k] = j;
                          values[k] = acc.value[static_cast<std::size_t>(j)];
                          ++k;
                        }
                      }
                    });
  return SparseMatrix(Eigen::Map<const SparseMatrix>(rows, cols, static_cast<Eigen::Index>(nnz),
                                                     outer.data(), inner.data(), values.data()));
}

SparseMatrix galerkin_product(const SparseMatrix& pt, const SparseMatrix& a,
                              const SparseMatrix& p) {
  return multiply(pt, multiply(a, p));
}

}  // namespace molmesh::solvers
