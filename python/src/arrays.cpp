#include "arrays.hpp"

#include <cstring>
#include <limits>

#include "casters.hpp"

namespace molmesh::python {

void check_shape(const py::array& array, py::ssize_t cols, const char* name) {
  const bool ok = cols == 0 ? array.ndim() == 1 : array.ndim() == 2 && array.shape(1) == cols;
  if (!ok) {
    std::string shape = "(";
    for (py::ssize_t i = 0; i < array.ndim(); ++i)
      shape += (i ? ", " : "") + std::to_string(array.shape(i));
    shape += array.ndim() == 1 ? ",)" : ")";
    throw py::value_error(std::string(name) + " must have shape " +
                          (cols == 0 ? "(n,)" : "(n, " + std::to_string(cols) + ")") + ", got " +
                          shape);
  }
}

std::vector<Vec3> to_points(const py::object& array, const char* name) {
  const InputDoubles a = InputDoubles::ensure(array);
  if (!a) throw py::type_error(std::string(name) + " must be a float array");
  check_shape(a, 3, name);
  std::vector<Vec3> points(static_cast<std::size_t>(a.shape(0)));
  if (!points.empty())
    std::memcpy(static_cast<void*>(points.data()), a.data(), points.size() * sizeof(Vec3));
  return points;
}

InputInts to_int_array(const py::object& array, const char* name) {
  const py::array any = py::array::ensure(array);
  if (!any) throw py::type_error(std::string(name) + " must be an integer array");
  const char kind = any.dtype().kind();
  if (any.size() > 0 && kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + " must be an integer array, got dtype " +
                         std::string(py::str(any.dtype())));
  const py::array_t<long long> wide =
      py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(any);
  const long long* v = wide.data();
  for (py::ssize_t i = 0; i < wide.size(); ++i) {
    if (v[i] < std::numeric_limits<int>::min() || v[i] > std::numeric_limits<int>::max())
      throw py::value_error(std::string(name) + " has a value beyond the int32 range");
  }
  return InputInts::ensure(any);
}

std::vector<int> to_ints(const py::object& array, const char* name) {
  const InputInts a = to_int_array(array, name);
  check_shape(a, 0, name);
  return std::vector<int>(a.data(), a.data() + a.shape(0));
}

std::vector<double> to_doubles(const py::object& array, const char* name) {
  const InputDoubles a = InputDoubles::ensure(array);
  if (!a) throw py::type_error(std::string(name) + " must be a float array");
  check_shape(a, 0, name);
  return std::vector<double>(a.data(), a.data() + a.shape(0));
}

}  // namespace molmesh::python
