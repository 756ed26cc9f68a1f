#include "molmesh/io/hdf5_file.hpp"

#include <algorithm>
#include <cstdint>
#include <cstring>

#include "molmesh/core/atomic_file.hpp"

namespace molmesh::hdf5 {
namespace {

template <class T>
struct H5TypeOf;
template <>
struct H5TypeOf<double> {
  static hid_t file() { return H5T_IEEE_F64LE; }
  static hid_t memory() { return H5T_NATIVE_DOUBLE; }
};
template <>
struct H5TypeOf<int> {
  static hid_t file() { return H5T_STD_I32LE; }
  static hid_t memory() { return H5T_NATIVE_INT; }
};
template <>
struct H5TypeOf<std::int64_t> {
  static hid_t file() { return H5T_STD_I64LE; }
  static hid_t memory() { return H5T_NATIVE_INT64; }
};

}  // namespace

void silence_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

void check(herr_t status, const std::string& what) {
  if (status < 0) throw H5Failure(what);
}

bool link_exists(hid_t loc, const std::string& path) {
  // H5Lexists needs every intermediate link to exist, so walk the path component-wise.
  std::string prefix;
  std::size_t start = path.front() == '/' ? 1 : 0;
  if (start == 1) prefix = "/";
  while (start <= path.size()) {
    const auto slash = path.find('/', start);
    const auto part =
        path.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
    prefix += part;
    if (H5Lexists(loc, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (slash == std::string::npos) break;
    prefix += '/';
    start = slash + 1;
  }
  return true;
}

Handle create_group(hid_t loc, const std::string& path) {
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose, "property list");
  check(H5Pset_create_intermediate_group(lcpl.get(), 1), "intermediate groups");
  Handle gcpl(H5Pcreate(H5P_GROUP_CREATE), H5Pclose, "property list");
  check(H5Pset_obj_track_times(gcpl.get(), 0), "object times");
  return Handle(H5Gcreate2(loc, path.c_str(), lcpl.get(), gcpl.get(), H5P_DEFAULT), H5Gclose,
                "cannot create group " + path);
}

// Chunked and deflate-compressed (shuffle first: it makes integer and coordinate arrays
// compress much better).
template <class T>
void write_dataset(hid_t loc, const std::string& name, const T* data, std::size_t rows,
                   std::size_t cols) {
  const int rank = cols == 0 ? 1 : 2;
  const hsize_t dims[2] = {rows, cols};
  Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose, "dataspace for " + name);
  Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "property list");
  // No modification times in the object headers: the same hierarchy gives the same bytes,
  // whenever and with however many threads it was built (tests/hierarchy/thread_independence).
  check(H5Pset_obj_track_times(dcpl.get(), 0), "object times");
  if (rows > 0) {
    const hsize_t chunk_rows = std::min<hsize_t>(rows, cols == 0 ? 65536 : 16384);
    const hsize_t chunk[2] = {chunk_rows, cols};
    check(H5Pset_chunk(dcpl.get(), rank, chunk), "chunking " + name);
    check(H5Pset_shuffle(dcpl.get()), "shuffle filter");
    check(H5Pset_deflate(dcpl.get(), 4), "deflate filter");
  }
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose, "property list");
  check(H5Pset_create_intermediate_group(lcpl.get(), 1), "intermediate groups");
  Handle set(H5Dcreate2(loc, name.c_str(), H5TypeOf<T>::file(), space.get(), lcpl.get(), dcpl.get(),
                        H5P_DEFAULT),
             H5Dclose, "cannot create dataset " + name);
  if (rows > 0) {
    check(H5Dwrite(set.get(), H5TypeOf<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data),
          "cannot write dataset " + name);
  }
}

void write_points(hid_t loc, const std::string& name, const std::vector<Vec3>& points) {
  std::vector<double> flat(points.size() * 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int d = 0; d < 3; ++d) flat[3 * i + static_cast<std::size_t>(d)] = points[i][d];
  }
  write_dataset(loc, name, flat.data(), points.size(), 3);
}

template <class T>
std::vector<T> read_dataset(hid_t loc, const std::string& name, std::size_t cols,
                            std::size_t* rows_out) {
  if (!link_exists(loc, name)) throw H5Failure("missing dataset " + name);
  Handle set(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, "cannot open " + name);
  Handle space(H5Dget_space(set.get()), H5Sclose, "dataspace of " + name);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  hsize_t dims[2] = {0, 0};
  if (rank != (cols == 0 ? 1 : 2) || H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0 ||
      (cols != 0 && dims[1] != cols)) {
    throw H5Failure("dataset " + name + " has the wrong shape (expected " +
                    (cols == 0 ? std::string("1-D") : "N x " + std::to_string(cols)) + ")");
  }
  const std::size_t rows = dims[0];
  // A damaged header can declare any size: refuse more values than the file could hold
  // (deflate compresses at most ~1032:1) before allocating them.
  hsize_t file_bytes = 0;
  {
    Handle owner(H5Iget_file_id(loc), H5Fclose, "file of " + name);
    check(H5Fget_filesize(owner.get(), &file_bytes), "size of the file");
  }
  const double bytes = static_cast<double>(rows) * static_cast<double>(cols == 0 ? 1 : cols) *
                       static_cast<double>(sizeof(T));
  if (bytes > 1100.0 * static_cast<double>(file_bytes) + 1048576.0)
    throw H5Failure("dataset " + name + " declares " + std::to_string(rows) +
                    " rows, more than the file can hold");
  if (rows_out) *rows_out = rows;
  std::vector<T> values(rows * (cols == 0 ? 1 : cols));
  if (!values.empty()) {
    check(H5Dread(set.get(), H5TypeOf<T>::memory(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()),
          "cannot read " + name);
  }
  return values;
}

std::vector<Vec3> read_points(hid_t loc, const std::string& name) {
  std::size_t rows = 0;
  const auto flat = read_dataset<double>(loc, name, 3, &rows);
  std::vector<Vec3> points(rows);
  for (std::size_t i = 0; i < rows; ++i)
    points[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  return points;
}

std::size_t dataset_rows(hid_t loc, const std::string& name) {
  Handle set(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), H5Dclose, "cannot open " + name);
  Handle space(H5Dget_space(set.get()), H5Sclose, "dataspace of " + name);
  hsize_t dims[2] = {0, 0};
  if (H5Sget_simple_extent_ndims(space.get()) < 1 ||
      H5Sget_simple_extent_dims(space.get(), dims, nullptr) < 0) {
    throw H5Failure("cannot read the shape of " + name);
  }
  return dims[0];
}

void write_string_attribute(hid_t loc, const std::string& name, const std::string& value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
  check(H5Tset_size(type.get(), H5T_VARIABLE), "string type");
  check(H5Tset_cset(type.get(), H5T_CSET_UTF8), "string type");
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "scalar space");
  if (H5Aexists(loc, name.c_str()) > 0) check(H5Adelete(loc, name.c_str()), "attribute " + name);
  Handle attribute(H5Acreate2(loc, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                   H5Aclose, "cannot create attribute " + name);
  const char* text = value.c_str();
  check(H5Awrite(attribute.get(), type.get(), &text), "cannot write attribute " + name);
}

template <class T>
void write_array_attribute(hid_t loc, const std::string& name, const std::vector<T>& values,
                           bool scalar) {
  const hsize_t dims[1] = {values.size()};
  Handle space(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, dims, nullptr), H5Sclose,
               "attribute space");
  Handle attribute(
      H5Acreate2(loc, name.c_str(), H5TypeOf<T>::file(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Aclose, "cannot create attribute " + name);
  if (!values.empty()) {
    check(H5Awrite(attribute.get(), H5TypeOf<T>::memory(), values.data()),
          "cannot write attribute " + name);
  }
}

std::optional<std::string> read_string_attribute(hid_t loc, const std::string& name) {
  if (H5Aexists(loc, name.c_str()) <= 0) return std::nullopt;
  Handle attribute(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose, "attribute " + name);
  Handle type(H5Aget_type(attribute.get()), H5Tclose, "attribute type");
  if (H5Tget_class(type.get()) != H5T_STRING) return std::nullopt;
  if (H5Tis_variable_str(type.get()) > 0) {
    Handle memory(H5Tcopy(H5T_C_S1), H5Tclose, "string type");
    check(H5Tset_size(memory.get(), H5T_VARIABLE), "string type");
    check(H5Tset_cset(memory.get(), H5Tget_cset(type.get())), "string type");
    char* text = nullptr;
    check(H5Aread(attribute.get(), memory.get(), &text), "cannot read attribute " + name);
    std::string value = text ? text : "";
    H5free_memory(text);
    return value;
  }
  const std::size_t size = H5Tget_size(type.get());
  std::string value(size, '\0');
  check(H5Aread(attribute.get(), type.get(), value.data()), "cannot read attribute " + name);
  value.resize(std::strlen(value.c_str()));
  return value;
}

template <class T>
std::vector<T> read_array_attribute(hid_t loc, const std::string& name) {
  if (H5Aexists(loc, name.c_str()) <= 0) throw H5Failure("missing attribute " + name);
  Handle attribute(H5Aopen(loc, name.c_str(), H5P_DEFAULT), H5Aclose, "attribute " + name);
  Handle space(H5Aget_space(attribute.get()), H5Sclose, "attribute space");
  const auto count = H5Sget_simple_extent_npoints(space.get());
  if (count < 0) throw H5Failure("attribute " + name);
  std::vector<T> values(static_cast<std::size_t>(count));
  if (!values.empty()) {
    check(H5Aread(attribute.get(), H5TypeOf<T>::memory(), values.data()),
          "cannot read attribute " + name);
  }
  return values;
}

Handle in_memory_access() {
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "file access list");
  // Readable by HDF5 1.8 and later (h5py, ParaView) while allowing compact new-style groups.
  check(H5Pset_libver_bounds(fapl.get(), H5F_LIBVER_EARLIEST, H5F_LIBVER_LATEST), "libver");
  check(H5Pset_fapl_core(fapl.get(), 1 << 20, 0), "memory file driver");
  return fapl;
}

std::vector<char> file_image(hid_t file) {
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), "flush");
  const ssize_t size = H5Fget_file_image(file, nullptr, 0);
  if (size <= 0) throw H5Failure("size of the file image");
  std::vector<char> image(static_cast<std::size_t>(size));
  if (H5Fget_file_image(file, image.data(), image.size()) != size) throw H5Failure("file image");
  return image;
}

void write_image(const std::filesystem::path& path, const std::vector<char>& image) {
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out.write(image.data(), static_cast<std::streamsize>(image.size()));
      },
      true);
}

template void write_dataset(hid_t, const std::string&, const double*, std::size_t, std::size_t);
template void write_dataset(hid_t, const std::string&, const int*, std::size_t, std::size_t);
template void write_dataset(hid_t, const std::string&, const std::int64_t*, std::size_t,
                            std::size_t);
template std::vector<double> read_dataset(hid_t, const std::string&, std::size_t, std::size_t*);
template std::vector<int> read_dataset(hid_t, const std::string&, std::size_t, std::size_t*);
template std::vector<std::int64_t> read_dataset(hid_t, const std::string&, std::size_t,
                                                std::size_t*);
template void write_array_attribute(hid_t, const std::string&, const std::vector<double>&, bool);
template void write_array_attribute(hid_t, const std::string&, const std::vector<int>&, bool);
template void write_array_attribute(hid_t, const std::string&, const std::vector<std::int64_t>&,
                                    bool);
template std::vector<double> read_array_attribute(hid_t, const std::string&);
template std::vector<int> read_array_attribute(hid_t, const std::string&);
template std::vector<std::int64_t> read_array_attribute(hid_t, const std::string&);

}  // namespace molmesh::hdf5
