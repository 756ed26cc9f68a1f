#include "solvers/fem/dirichlet.hpp"

#include "molmesh/core/error.hpp"

namespace molmesh::solvers {

std::vector<unsigned> boundary_vertex_marker_bits(const TetMesh& mesh) {
  std::vector<unsigned> bits(mesh.points.size(), 0u);
  for (std::size_t f = 0; f < mesh.boundary_faces.size(); ++f) {
    const int marker = f < mesh.boundary_face_markers.size() ? mesh.boundary_face_markers[f] : 0;
    if (marker < 0 || marker > 30) continue;
    for (int v : mesh.boundary_faces[f]) bits[static_cast<std::size_t>(v)] |= 1u << marker;
  }
  return bits;
}

unsigned marker_mask(std::span<const int> markers) {
  unsigned mask = 0;
  for (int m : markers) {
    if (m >= 0 && m <= 30) mask |= 1u << m;
  }
  return mask;
}

ReducedSystem number_free_vertices(std::span<const char> is_dirichlet) {
  ReducedSystem s;
  s.full_to_free.assign(is_dirichlet.size(), -1);
  for (std::size_t v = 0; v < is_dirichlet.size(); ++v) {
    if (!is_dirichlet[v]) {
      s.full_to_free[v] = static_cast<int>(s.free_to_full.size());
      s.free_to_full.push_back(static_cast<int>(v));
    }
  }
  if (s.free_to_full.empty()) throw Error("every vertex has a Dirichlet value: nothing to solve");
  return s;
}

ReducedSystem reduce_dirichlet(const SparseMatrix& a, const Eigen::VectorXd& b,
                               std::span<const char> is_dirichlet, const Eigen::VectorXd& values) {
  const auto n = static_cast<std::size_t>(a.rows());
  if (is_dirichlet.size() != n || static_cast<std::size_t>(b.size()) != n ||
      static_cast<std::size_t>(values.size()) != n) {
    throw Error("reduce_dirichlet: sizes of matrix, right-hand side and markers differ");
  }
  ReducedSystem s = number_free_vertices(is_dirichlet);
  const auto nf = static_cast<Eigen::Index>(s.free_to_full.size());
  s.rhs.resize(nf);
  // Free rows keep their order and columns are renumbered monotonically, so the reduced
  // matrix is written row by row, already sorted, straight into its storage (sized for
  // the worst case; pages never written are never touched).
  s.matrix.resize(nf, nf);
  s.matrix.resizeNonZeros(a.nonZeros());
  int* outer = s.matrix.outerIndexPtr();
  int* inner = s.matrix.innerIndexPtr();
  double* kept = s.matrix.valuePtr();
  int count = 0;
  outer[0] = 0;
  for (Eigen::Index i = 0; i < nf; ++i) {
    const int row = s.free_to_full[static_cast<std::size_t>(i)];
    double r = b[row];
    for (SparseMatrix::InnerIterator it(a, row); it; ++it) {
      const int col = s.full_to_free[static_cast<std::size_t>(it.col())];
      if (col >= 0) {
        inner[count] = col;
        kept[count] = it.value();
        ++count;
      } else {
        r -= it.value() * values[it.col()];
      }
    }
    s.rhs[i] = r;
    outer[i + 1] = count;
  }
  s.matrix.resizeNonZeros(count);
  return s;
}

Eigen::VectorXd expand_solution(const ReducedSystem& system, const Eigen::VectorXd& free_values,
                                std::span<const char> is_dirichlet, const Eigen::VectorXd& values) {
  Eigen::VectorXd full(static_cast<Eigen::Index>(is_dirichlet.size()));
  for (std::size_t v = 0; v < is_dirichlet.size(); ++v) {
    const int f = system.full_to_free[v];
    full[static_cast<Eigen::Index>(v)] =
        f >= 0 ? free_values[f] : values[static_cast<Eigen::Index>(v)];
  }
  return full;
}

}  // namespace molmesh::solvers
