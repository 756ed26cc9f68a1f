#include "solvers/multigrid/gauss_seidel.hpp"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <string>

#include "molmesh/core/error.hpp"

namespace molmesh::solvers {

GaussSeidelSmoother make_gauss_seidel(const SparseMatrix& a, int blocks,
                                      Eigen::Index min_rows_per_block) {
  if (!a.isCompressed()) throw Error("Gauss-Seidel: the operator must be compressed");
  GaussSeidelSmoother s;
  s.a = &a;
  const auto n = a.rows();
  s.inverse_diagonal.resize(n);
  s.diagonal.resize(static_cast<std::size_t>(n));
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  for (Eigen::Index i = 0; i < n; ++i) {
    const int* end = inner + outer[i + 1];
    const int* found = std::lower_bound(inner + outer[i], end, static_cast<int>(i));
    const double aii = found != end && *found == i ? a.valuePtr()[found - inner] : 0.0;
    if (!(aii > 0.0)) {
      throw Error("multigrid: row " + std::to_string(i) +
                  " of a level's operator has no positive diagonal entry; the operator is "
                  "not symmetric positive definite");
    }
    s.diagonal[static_cast<std::size_t>(i)] = static_cast<int>(found - inner);
    s.inverse_diagonal[i] = 1.0 / aii;
  }
  const Eigen::Index count = std::clamp<Eigen::Index>(
      n / std::max<Eigen::Index>(min_rows_per_block, 1), 1, std::max(blocks, 1));
  for (Eigen::Index b = 0; b <= count; ++b) s.block.push_back(b * n / count);
  for (std::size_t b = 0; b + 1 < s.block.size(); ++b) {
    for (Eigen::Index i = s.block[b]; i < s.block[b + 1]; ++i) {
      // Columns are sorted: the first and last entries tell.
      if (outer[i] < outer[i + 1] &&
          (inner[outer[i]] < s.block[b] || inner[outer[i + 1] - 1] >= s.block[b + 1]))
        s.cross_block_rows.push_back(i);
    }
  }
  return s;
}

namespace {

// Runs body(lo, hi) for every block, blocks in parallel.
template <class Body>
void for_each_block(const GaussSeidelSmoother& s, const Body& body) {
  const std::size_t blocks = s.block.size() - 1;
  if (blocks == 1) {
    body(s.block[0], s.block[1]);
    return;
  }
  tbb::parallel_for(std::size_t{0}, blocks,
                    [&](std::size_t b) { body(s.block[b], s.block[b + 1]); });
}

// One sweep over every block; rows of other blocks are read from `start`, x as it was
// when the sweep began (with one block, x itself: no other block reads it).
template <bool kForward>
void sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd& b, Eigen::VectorXd& x,
           Eigen::VectorXd* start) {
  const int* outer = s.a->outerIndexPtr();
  const int* inner = s.a->innerIndexPtr();
  const double* values = s.a->valuePtr();
  Eigen::VectorXd local;
  if (s.block.size() > 2) {
    if (!start) start = &local;
    *start = x;
  }
  const double* old_x = s.block.size() > 2 ? start->data() : x.data();
  double* new_x = x.data();
  for_each_block(s, [&](Eigen::Index lo, Eigen::Index hi) {
    const auto width = static_cast<unsigned>(hi - lo);
    auto relax = [&](Eigen::Index i) {
      double sum = b[i];
      for (int k = outer[i]; k < outer[i + 1]; ++k) {
        const int j = inner[k];
        const bool here = static_cast<unsigned>(j - lo) < width;
        sum -= values[k] * (here ? new_x[j] : old_x[j]);
      }
      // The loop subtracted the diagonal term too; the update adds it back.
      new_x[i] += sum * s.inverse_diagonal[i];
    };
    if constexpr (kForward) {
      for (Eigen::Index i = lo; i < hi; ++i) relax(i);
    } else {
      for (Eigen::Index i = hi - 1; i >= lo; --i) relax(i);
    }
  });
}

}  // namespace

void forward_sweep_from_zero(const GaussSeidelSmoother& s, const Eigen::VectorXd& b,
                             Eigen::VectorXd& x) {
  const int* outer = s.a->outerIndexPtr();
  const int* inner = s.a->innerIndexPtr();
  const double* values = s.a->valuePtr();
  x.resize(s.a->rows());
  for_each_block(s, [&](Eigen::Index lo, Eigen::Index hi) {
    for (Eigen::Index i = lo; i < hi; ++i) {
      double sum = b[i];
      // Left of the diagonal and inside the block: everything else is still zero.
      for (int k = s.diagonal[static_cast<std::size_t>(i)] - 1; k >= outer[i] && inner[k] >= lo;
           --k)
        sum -= values[k] * x[inner[k]];
      x[i] = sum * s.inverse_diagonal[i];
    }
  });
}

void forward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                   Eigen::VectorXd* sweep_start) {
  sweep<true>(s, b, x, sweep_start);
}

void backward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd& b, Eigen::VectorXd& x,
                    Eigen::VectorXd* sweep_start) {
  sweep<false>(s, b, x, sweep_start);
}

namespace {

// The block holding row i.
std::size_t block_of(const GaussSeidelSmoother& s, Eigen::Index i) {
  return static_cast<std::size_t>(std::upper_bound(s.block.begin(), s.block.end(), i) -
                                  s.block.begin()) -
         1;
}

// For every row at a block face, in parallel: out_i += sum of a_ij term(j) over the entries
// j in other blocks.
template <class Term>
void add_cross_block_terms(const GaussSeidelSmoother& s, Eigen::VectorXd& out, const Term& term) {
  const int* outer = s.a->outerIndexPtr();
  const int* inner = s.a->innerIndexPtr();
  const double* values = s.a->valuePtr();
  const auto& rows = s.cross_block_rows;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, rows.size(), 256),
                    [&](const tbb::blocked_range<std::size_t>& range) {
                      for (std::size_t r = range.begin(); r != range.end(); ++r) {
                        const Eigen::Index i = rows[r];
                        const std::size_t b = block_of(s, i);
                        const int lo = static_cast<int>(s.block[b]);
                        const int hi = static_cast<int>(s.block[b + 1]);
                        double sum = 0.0;
                        for (int k = outer[i]; k < outer[i + 1]; ++k) {
                          const int j = inner[k];
                          if (j < lo || j >= hi) sum += values[k] * term(j);
                        }
                        out[i] += sum;
                      }
                    });
}

}  // namespace

void forward_sweep_from_zero_with_residual(const GaussSeidelSmoother& s, const Eigen::VectorXd& b,
                                           Eigen::VectorXd& x, Eigen::VectorXd& residual) {
  const int* outer = s.a->outerIndexPtr();
  const int* inner = s.a->innerIndexPtr();
  const double* values = s.a->valuePtr();
  x.resize(s.a->rows());
  residual.resize(s.a->rows());
  for_each_block(s, [&](Eigen::Index lo, Eigen::Index hi) {
    for (Eigen::Index i = lo; i < hi; ++i) {
      const int diagonal = s.diagonal[static_cast<std::size_t>(i)];
      int first = outer[i];  // the first entry of this block
      while (inner[first] < lo) ++first;
      double sum = b[i];
      // Left of the diagonal and inside the block: everything else is still zero.
      for (int k = first; k < diagonal; ++k) sum -= values[k] * x[inner[k]];
      const double xi = sum * s.inverse_diagonal[i];
      x[i] = xi;
      // Row i is now satisfied; the earlier rows j of the block were satisfied with x_i = 0
      // and now miss -a_ji x_i (every contribution to residual_i comes from later rows).
      residual[i] = 0.0;
      for (int k = first; k < diagonal; ++k) residual[inner[k]] -= values[k] * xi;
    }
  });
  add_cross_block_terms(s, residual, [&](int j) { return -x[j]; });
}

void backward_sweep_with_product(const GaussSeidelSmoother& s, const Eigen::VectorXd& b,
                                 Eigen::VectorXd& x, Eigen::VectorXd& sweep_start,
                                 Eigen::VectorXd& ax) {
  const int* outer = s.a->outerIndexPtr();
  const int* inner = s.a->innerIndexPtr();
  const double* values = s.a->valuePtr();
  const bool several_blocks = s.block.size() > 2;
  if (several_blocks) sweep_start = x;
  const double* start_x = several_blocks ? sweep_start.data() : x.data();
  double* new_x = x.data();
  ax.resize(s.a->rows());
  for_each_block(s, [&](Eigen::Index lo, Eigen::Index hi) {
    const auto width = static_cast<unsigned>(hi - lo);
    for (Eigen::Index i = hi - 1; i >= lo; --i) {
      const int diagonal = s.diagonal[static_cast<std::size_t>(i)];
      double sum = b[i];
      for (int k = outer[i]; k < outer[i + 1]; ++k) {
        const int j = inner[k];
        const bool here = static_cast<unsigned>(j - lo) < width;
        sum -= values[k] * (here ? new_x[j] : start_x[j]);
      }
      const double delta = sum * s.inverse_diagonal[i];
      new_x[i] += delta;
      // Row i is satisfied now; the later rows of the block were satisfied with x_i's old
      // value and gain a_ji delta_i (every contribution to ax_i comes from earlier rows).
      ax[i] = b[i];
      for (int k = diagonal + 1; k < outer[i + 1] && inner[k] < hi; ++k)
        ax[inner[k]] += values[k] * delta;
    }
  });
  if (several_blocks) add_cross_block_terms(s, ax, [&](int j) { return new_x[j] - start_x[j]; });
}

void residual_after_forward_sweep(const GaussSeidelSmoother& s, const Eigen::VectorXd* before,
                                  const Eigen::VectorXd& after, Eigen::VectorXd& residual) {
  const int* outer = s.a->outerIndexPtr();
  const int* inner = s.a->innerIndexPtr();
  const double* values = s.a->valuePtr();
  residual.resize(s.a->rows());
  // Rows are independent here: within each block they go in parallel too.
  for_each_block(s, [&](Eigen::Index lo, Eigen::Index hi) {
    tbb::parallel_for(tbb::blocked_range<Eigen::Index>(lo, hi, 2048),
                      [&](const tbb::blocked_range<Eigen::Index>& rows) {
                        for (Eigen::Index i = rows.begin(); i != rows.end(); ++i) {
                          double sum = 0.0;
                          auto add = [&](int k) {
                            const int j = inner[k];
                            sum += values[k] * ((before ? (*before)[j] : 0.0) - after[j]);
                          };
                          // Earlier blocks, then right of the diagonal (later rows of this block
                          // and later blocks).
                          for (int k = outer[i]; k < outer[i + 1] && inner[k] < lo; ++k) add(k);
                          for (int k = s.diagonal[static_cast<std::size_t>(i)] + 1;
                               k < outer[i + 1]; ++k)
                            add(k);
                          residual[i] = sum;
                        }
                      });
  });
}

}  // namespace molmesh::solvers
