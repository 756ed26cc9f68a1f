#pragma once
// numpy views of the library's plain vectors without copying: an n x k array over
// contiguous rows (std::vector<Vec3>, std::vector<std::array<int, k>>, std::vector<int>),
// read-only, kept alive by `owner` (the Python object holding the C++ data). Inputs come
// the other way with one copy (py::array_t with forcecast + C order).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh::python {

namespace py = pybind11;

template <class T>
py::array read_only(py::array_t<T> array) {
  py::detail::array_proxy(array.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return array;
}

// rows x cols matrix of T at `data`, row-major.
template <class T>
py::array matrix_view(const T* data, std::size_t rows, std::size_t cols, py::handle owner) {
  const auto stride = static_cast<py::ssize_t>(sizeof(T));
  return read_only(py::array_t<T>({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)},
                                  {stride * static_cast<py::ssize_t>(cols), stride}, data, owner));
}

template <class T>
py::array vector_view(const std::vector<T>& v, py::handle owner) {
  return read_only(
      py::array_t<T>({static_cast<py::ssize_t>(v.size())}, {sizeof(T)}, v.data(), owner));
}

// n x 3 float64 (Eigen::Vector3d is three packed doubles).
inline py::array points_view(const std::vector<Vec3>& points, py::handle owner) {
  static_assert(sizeof(Vec3) == 3 * sizeof(double));
  return matrix_view(points.empty() ? nullptr : points.front().data(), points.size(), 3, owner);
}

// n x K int32.
template <std::size_t K>
py::array cells_view(const std::vector<std::array<int, K>>& cells, py::handle owner) {
  static_assert(sizeof(std::array<int, K>) == K * sizeof(int));
  return matrix_view(cells.empty() ? nullptr : cells.front().data(), cells.size(), K, owner);
}

using InputDoubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
using InputInts = py::array_t<int, py::array::c_style | py::array::forcecast>;

// Checks an input array's shape: (n, cols), or (n,) for cols == 0. Throws ValueError naming it.
// Integer input (any integer dtype, converted to int32); floats are refused, not truncated.
InputInts to_int_array(const py::object& array, const char* name);

void check_shape(const py::array& array, py::ssize_t cols, const char* name);

std::vector<Vec3> to_points(const py::object& array, const char* name);
template <std::size_t K>
std::vector<std::array<int, K>> to_cells(const py::object& array, const char* name) {
  const InputInts a = to_int_array(array, name);
  check_shape(a, static_cast<py::ssize_t>(K), name);
  std::vector<std::array<int, K>> cells(static_cast<std::size_t>(a.shape(0)));
  if (!cells.empty())
    std::memcpy(static_cast<void*>(cells.data()), a.data(), cells.size() * sizeof(cells[0]));
  return cells;
}
std::vector<int> to_ints(const py::object& array, const char* name);
std::vector<double> to_doubles(const py::object& array, const char* name);

}  // namespace molmesh::python
