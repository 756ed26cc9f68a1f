#pragma once
// Sparse matrices (e.g. a hierarchy's prolongations) for other solvers:
//   PETSc binary (what MatLoad reads): big-endian, MAT_FILE_CLASSID 1211216, int32 sizes
//   and column indices, float64 values (PETSc built with 32-bit indices and real scalars,
//   as Debian's petsc-dev is).
//   Matrix Market coordinate real general (.mtx; scipy.io.mmread, Octave, Julia),
//   1-based indices.
#include <filesystem>

#include "molmesh/hierarchy/hierarchy.hpp"

namespace molmesh {

// Both throw OutputError when the file cannot be written (atomically: no half files) and
// molmesh::Error when the matrix exceeds int32 sizes.
void write_petsc_binary(const std::filesystem::path& path, const SparseMatrix& matrix);
void write_matrix_market(const std::filesystem::path& path, const SparseMatrix& matrix,
                         const std::string& comment = {});

}  // namespace molmesh
