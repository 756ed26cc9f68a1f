#include "molmesh/io/sparse_matrix_io.hpp"

#include <bit>
#include <charconv>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"

namespace molmesh {
namespace {

constexpr std::int32_t kMatFileClassId = 1211216;  // PETSc's MAT_FILE_CLASSID

template <typename T>
void append_big_endian(std::vector<char>& out, T value) {
  static_assert(sizeof(T) == 4 || sizeof(T) == 8);
  using U = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
  const U bits = std::bit_cast<U>(value);
  for (int shift = 8 * static_cast<int>(sizeof(U)) - 8; shift >= 0; shift -= 8)
    out.push_back(static_cast<char>((bits >> shift) & 0xff));
}

void require_int32(const SparseMatrix& m, const std::filesystem::path& path) {
  if (m.nonZeros() > std::numeric_limits<std::int32_t>::max()) {
    throw Error(path.string() + ": " + std::to_string(m.nonZeros()) +
                " nonzeros exceed the int32 indices of PETSc's binary format");
  }
}

}  // namespace

void write_petsc_binary(const std::filesystem::path& path, const SparseMatrix& input) {
  require_int32(input, path);
  SparseMatrix m = input;
  m.makeCompressed();
  std::vector<char> bytes;
  bytes.reserve(16 + 4 * static_cast<std::size_t>(m.rows()) + 12 * m.nonZeros());
  // Header: classid, rows, columns, total nonzeros; then nonzeros per row, column indices
  // (row by row, ascending as Eigen stores them), values.
  append_big_endian(bytes, kMatFileClassId);
  append_big_endian(bytes, static_cast<std::int32_t>(m.rows()));
  append_big_endian(bytes, static_cast<std::int32_t>(m.cols()));
  append_big_endian(bytes, static_cast<std::int32_t>(m.nonZeros()));
  const int* outer = m.outerIndexPtr();
  for (Eigen::Index r = 0; r < m.rows(); ++r)
    append_big_endian(bytes, static_cast<std::int32_t>(outer[r + 1] - outer[r]));
  for (Eigen::Index k = 0; k < m.nonZeros(); ++k)
    append_big_endian(bytes, static_cast<std::int32_t>(m.innerIndexPtr()[k]));
  for (Eigen::Index k = 0; k < m.nonZeros(); ++k) append_big_endian(bytes, m.valuePtr()[k]);
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
      },
      /*binary=*/true);
}

void write_matrix_market(const std::filesystem::path& path, const SparseMatrix& m,
                         const std::string& comment) {
  require_int32(m, path);
  write_file_atomically(path, [&](std::ostream& out) {
    out << "%%MatrixMarket matrix coordinate real general\n";
    if (!comment.empty()) out << "% " << comment << '\n';
    out << m.rows() << ' ' << m.cols() << ' ' << m.nonZeros() << '\n';
    // Shortest round-trip text for every value: exact when read back.
    std::string line;
    char number[32];
    for (Eigen::Index r = 0; r < m.outerSize(); ++r) {
      for (SparseMatrix::InnerIterator it(m, r); it; ++it) {
        line.clear();
        line += std::to_string(r + 1);
        line += ' ';
        line += std::to_string(it.col() + 1);
        line += ' ';
        const auto end = std::to_chars(number, number + sizeof(number), it.value()).ptr;
        line.append(number, end);
        line += '\n';
        out << line;
      }
    }
  });
}

}  // namespace molmesh
