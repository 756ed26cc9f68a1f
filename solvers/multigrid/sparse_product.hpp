#pragma once
// Sparse matrix products for the multigrid setup. Eigen's sparse product is serial and
// allocates per column; on a 50k-unknown mesh level the Galerkin products P^T A P took most
// of the setup. This is Gustavson's row-by-row product, rows in parallel, in two passes
// (count, then fill) so the result is allocated once.
#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh::solvers {

// a * b. Columns within a row are sorted; every entry is summed in the order of a's row
// and then b's row, so the result does not depend on the thread count.
SparseMatrix multiply(const SparseMatrix& a, const SparseMatrix& b);

// P^T A P (the Galerkin coarse operator), with pt = P^T given.
SparseMatrix galerkin_product(const SparseMatrix& pt, const SparseMatrix& a, const SparseMatrix& p);

}  // namespace molmesh::solvers
