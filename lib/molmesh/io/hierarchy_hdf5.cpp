#include "molmesh/io/hierarchy_hdf5.hpp"

#include <hdf5.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <optional>
#include <set>
#include <stdexcept>
#include <utility>

#include "molmesh/core/atomic_file.hpp"
#include "molmesh/core/error.hpp"
#include "molmesh/io/xdmf.hpp"
#include "molmesh/tetmesh/markers.hpp"

namespace molmesh {
namespace {

// Internal failure of one HDF5 call; the public entry points turn it into InputError or
// OutputError naming the file.
struct H5Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The library never prints: silence HDF5's default error-stack dump on stderr.
void silence_hdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer, const std::string& what) : id_(id), close_(closer) {
    if (id_ < 0) throw H5Failure(what);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept { *this = std::move(other); }
  Handle& operator=(Handle&& other) noexcept {
    reset();
    id_ = std::exchange(other.id_, -1);
    close_ = other.close_;
    return *this;
  }
  ~Handle() { reset(); }
  hid_t get() const { return id_; }

 private:
  void reset() {
    if (id_ >= 0 && close_) close_(id_);
    id_ = -1;
  }
  hid_t id_ = -1;
  Closer close_ = nullptr;
};

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

// rows x cols (cols = 0: a 1-D dataset of `rows` values), chunked and deflate-compressed
// (shuffle first: it makes integer and coordinate arrays compress much better).
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

template <class T>
void write_vector(hid_t loc, const std::string& name, const std::vector<T>& values) {
  write_dataset(loc, name, values.data(), values.size(), 0);
}

void write_points(hid_t loc, const std::string& name, const std::vector<Vec3>& points) {
  std::vector<double> flat(points.size() * 3);
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int d = 0; d < 3; ++d) flat[3 * i + static_cast<std::size_t>(d)] = points[i][d];
  }
  write_dataset(loc, name, flat.data(), points.size(), 3);
}

template <std::size_t N>
void write_cells(hid_t loc, const std::string& name, const std::vector<std::array<int, N>>& cells) {
  write_dataset(loc, name, cells.empty() ? nullptr : cells.front().data(), cells.size(), N);
}

// Reads a dataset as T; `cols` 0 means 1-D. Returns the values and the row count.
template <class T>
std::vector<T> read_dataset(hid_t loc, const std::string& name, std::size_t cols,
                            std::size_t* rows_out = nullptr) {
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

template <std::size_t N>
std::vector<std::array<int, N>> read_cells(hid_t loc, const std::string& name) {
  std::size_t rows = 0;
  const auto flat = read_dataset<int>(loc, name, N, &rows);
  std::vector<std::array<int, N>> cells(rows);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t k = 0; k < N; ++k) cells[i][k] = flat[N * i + k];
  }
  return cells;
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

// --- attributes ---------------------------------------------------------------------------

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
                           bool scalar = false) {
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

// --- layout ---------------------------------------------------------------------------------

std::string level_path(int level) { return "/levels/" + std::to_string(level); }
std::string transfer_path(int coarse, int fine) {
  return "/transfer/" + std::to_string(coarse) + "_to_" + std::to_string(fine);
}
constexpr const char* kParameterPrefix = "param.";

void write_csr(hid_t file, const std::string& group_path, const SparseMatrix& input) {
  SparseMatrix matrix = input;
  matrix.makeCompressed();
  Handle group = create_group(file, group_path);
  const auto nnz = static_cast<std::size_t>(matrix.nonZeros());
  std::vector<std::int64_t> indptr(static_cast<std::size_t>(matrix.rows()) + 1);
  for (std::size_t i = 0; i < indptr.size(); ++i) indptr[i] = matrix.outerIndexPtr()[i];
  write_dataset(group.get(), "data", matrix.valuePtr(), nnz, 0);
  write_dataset(group.get(), "indices", matrix.innerIndexPtr(), nnz, 0);
  write_vector(group.get(), "indptr", indptr);
  write_array_attribute<std::int64_t>(group.get(), "shape", {matrix.rows(), matrix.cols()});
  write_string_attribute(group.get(), "format", "csr");
}

SparseMatrix read_csr(hid_t file, const std::string& group_path) {
  const auto shape = read_array_attribute<std::int64_t>(
      Handle(H5Gopen2(file, group_path.c_str(), H5P_DEFAULT), H5Gclose, "missing " + group_path)
          .get(),
      "shape");
  if (shape.size() != 2 || shape[0] < 0 || shape[1] < 0)
    throw H5Failure(group_path + ": bad shape");
  const auto data = read_dataset<double>(file, group_path + "/data", 0);
  const auto indices = read_dataset<int>(file, group_path + "/indices", 0);
  const auto indptr64 = read_dataset<std::int64_t>(file, group_path + "/indptr", 0);
  if (indptr64.size() != static_cast<std::size_t>(shape[0]) + 1 || indices.size() != data.size() ||
      indptr64.front() != 0 || indptr64.back() != static_cast<std::int64_t>(data.size())) {
    throw H5Failure(group_path + ": inconsistent CSR arrays");
  }
  std::vector<int> indptr(indptr64.size());
  for (std::size_t i = 0; i < indptr.size(); ++i) {
    if (i > 0 && indptr64[i] < indptr64[i - 1]) throw H5Failure(group_path + ": bad indptr");
    indptr[i] = static_cast<int>(indptr64[i]);
  }
  for (int column : indices) {
    if (column < 0 || column >= shape[1]) throw H5Failure(group_path + ": column out of range");
  }
  const Eigen::Map<const SparseMatrix> view(shape[0], shape[1],
                                            static_cast<Eigen::Index>(data.size()), indptr.data(),
                                            indices.data(), data.data());
  return SparseMatrix(view);
}

void write_level(hid_t file, int index, const HierarchyLevel& level) {
  const auto base = level_path(index);
  {
    Handle group = create_group(file, base);
    write_array_attribute<double>(group.get(), "t0", {level.t0}, true);
  }
  const auto surface = base + "/surface/";
  write_points(file, surface + "points", level.surface.points);
  write_cells(file, surface + "triangles", level.surface.triangles);
  write_vector(file, surface + "vertex_markers", level.surface.vertex_markers);
  write_vector(file, surface + "face_markers", level.surface.face_markers);
  write_vector(file, surface + "provenance", level.surface_provenance);
  const auto volume = base + "/volume/";
  write_points(file, volume + "points", level.volume.points);
  write_cells(file, volume + "tetrahedra", level.volume.tetrahedra);
  write_vector(file, volume + "cell_markers", level.volume.cell_markers);
  write_vector(file, volume + "vertex_markers", level.volume.vertex_markers);
  write_cells(file, volume + "boundary_faces", level.volume.boundary_faces);
  write_vector(file, volume + "boundary_face_markers", level.volume.boundary_face_markers);
  write_vector(file, volume + "permutation", level.volume_permutation);
  create_group(file, volume + "fields");
}

// Contents a solver would trust: sizes agree, values are finite, markers are ones the
// mesher writes (markers.hpp), the permutation is one. A damaged file must be refused here
// rather than produce garbage or crash later.
void check_finite(const std::vector<Vec3>& points, const std::string& what) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!points[i].allFinite())
      throw H5Failure(what + ": point " + std::to_string(i) + " is not finite");
}

void check_length(std::size_t got, std::size_t want, const std::string& what, bool may_be_empty) {
  if (got == want || (may_be_empty && got == 0)) return;
  throw H5Failure(what + " has " + std::to_string(got) + " values, expected " +
                  std::to_string(want));
}

void check_values(const std::vector<int>& values, std::initializer_list<int> allowed,
                  const std::string& what) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (std::find(allowed.begin(), allowed.end(), values[i]) == allowed.end())
      throw H5Failure(what + "[" + std::to_string(i) + "] = " + std::to_string(values[i]) +
                      " is not a valid marker");
}

void validate_level(const HierarchyLevel& level, const std::string& base) {
  using namespace markers;
  if (!std::isfinite(level.t0)) throw H5Failure(base + ": t0 is not finite");
  const SurfaceMesh& s = level.surface;
  check_finite(s.points, base + "/surface/points");
  check_length(s.vertex_markers.size(), s.points.size(), base + "/surface/vertex_markers", true);
  check_length(s.face_markers.size(), s.triangles.size(), base + "/surface/face_markers", true);
  const TetMesh& v = level.volume;
  const std::string volume = base + "/volume/";
  check_finite(v.points, volume + "points");
  check_length(v.cell_markers.size(), v.tetrahedra.size(), volume + "cell_markers", false);
  check_values(v.cell_markers, {kMoleculeRegion, kSolventRegion}, volume + "cell_markers");
  check_length(v.vertex_markers.size(), v.points.size(), volume + "vertex_markers", false);
  check_values(v.vertex_markers, {kNoMarker, kMolecularSurface, kOuterSphere, kActiveSite},
               volume + "vertex_markers");
  check_length(v.boundary_face_markers.size(), v.boundary_faces.size(),
               volume + "boundary_face_markers", false);
  check_values(v.boundary_face_markers, {kNoMarker, kMolecularSurface, kOuterSphere, kActiveSite},
               volume + "boundary_face_markers");
  const auto& permutation = level.volume_permutation;
  check_length(permutation.size(), v.points.size(), volume + "permutation", true);
  std::vector<char> seen(permutation.size(), 0);
  for (std::size_t i = 0; i < permutation.size(); ++i) {
    const int p = permutation[i];
    if (p < 0 || static_cast<std::size_t>(p) >= permutation.size() || seen[p])
      throw H5Failure(volume + "permutation[" + std::to_string(i) + "] = " + std::to_string(p) +
                      " is not a permutation of 0.." + std::to_string(permutation.size() - 1));
    seen[p] = 1;
  }
}

HierarchyLevel read_level(hid_t file, int index) {
  const auto base = level_path(index);
  if (!link_exists(file, base)) throw H5Failure("missing group " + base);
  HierarchyLevel level;
  {
    Handle group(H5Gopen2(file, base.c_str(), H5P_DEFAULT), H5Gclose, "group " + base);
    const auto t0 = read_array_attribute<double>(group.get(), "t0");
    if (t0.size() != 1) throw H5Failure(base + ": bad t0 attribute");
    level.t0 = t0.front();
  }
  const auto surface = base + "/surface/";
  level.surface.points = read_points(file, surface + "points");
  level.surface.triangles = read_cells<3>(file, surface + "triangles");
  level.surface.vertex_markers = read_dataset<int>(file, surface + "vertex_markers", 0);
  level.surface.face_markers = read_dataset<int>(file, surface + "face_markers", 0);
  level.surface_provenance = read_dataset<int>(file, surface + "provenance", 0);
  const auto volume = base + "/volume/";
  level.volume.points = read_points(file, volume + "points");
  level.volume.tetrahedra = read_cells<4>(file, volume + "tetrahedra");
  level.volume.cell_markers = read_dataset<int>(file, volume + "cell_markers", 0);
  level.volume.vertex_markers = read_dataset<int>(file, volume + "vertex_markers", 0);
  level.volume.boundary_faces = read_cells<3>(file, volume + "boundary_faces");
  level.volume.boundary_face_markers = read_dataset<int>(file, volume + "boundary_face_markers", 0);
  level.volume_permutation = read_dataset<int>(file, volume + "permutation", 0);

  const auto check_range = [&](const auto& cells, std::size_t n, const std::string& what) {
    for (const auto& cell : cells) {
      for (int v : cell) {
        if (v < 0 || static_cast<std::size_t>(v) >= n) {
          throw H5Failure(base + "/" + what + ": vertex index out of range");
        }
      }
    }
  };
  check_range(level.surface.triangles, level.surface.points.size(), "surface/triangles");
  check_range(level.volume.tetrahedra, level.volume.points.size(), "volume/tetrahedra");
  check_range(level.volume.boundary_faces, level.volume.points.size(), "volume/boundary_faces");
  validate_level(level, base);
  return level;
}

// Opens an existing file and checks it is a molmesh hierarchy; returns it and its level count.
// Only for files already probed (probe_hierarchy) or just written by us.
std::pair<Handle, int> open_unprobed(const std::filesystem::path& path, unsigned flags) {
  silence_hdf5();
  if (!std::filesystem::exists(path)) throw InputError(path.string(), "no such file");
  if (H5Fis_hdf5(path.c_str()) <= 0) {
    throw InputError(path.string(), "not an HDF5 file (expected a molmesh hierarchy .h5)");
  }
  Handle file;
  try {
    file = Handle(H5Fopen(path.c_str(), flags, H5P_DEFAULT), H5Fclose, "cannot open");
  } catch (const H5Failure&) {
    throw InputError(path.string(), "cannot open the HDF5 file");
  }
  std::optional<std::string> format;
  try {
    format = read_string_attribute(file.get(), "format");
  } catch (const H5Failure& e) {
    throw InputError(path.string(), std::string("damaged HDF5 file: ") + e.what());
  }
  if (!format || *format != kHierarchyFormatName) {
    throw InputError(path.string(), "not a molmesh hierarchy (no root attribute format=\"" +
                                        std::string(kHierarchyFormatName) + "\")");
  }
  int levels = 0;
  try {
    const auto version = read_array_attribute<int>(file.get(), "format_version");
    if (version.size() != 1 || version.front() > kHierarchyFormatVersion) {
      throw InputError(path.string(),
                       "hierarchy format version " +
                           (version.empty() ? std::string("?") : std::to_string(version.front())) +
                           " is newer than this molmesh understands (" +
                           std::to_string(kHierarchyFormatVersion) + ")");
    }
    const auto count = read_array_attribute<int>(file.get(), "num_levels");
    if (count.size() != 1 || count.front() < 0) throw H5Failure("bad num_levels attribute");
    levels = count.front();
  } catch (const H5Failure& e) {
    throw InputError(path.string(), e.what());
  }
  return {std::move(file), levels};
}

std::string sidecar_name(const std::filesystem::path& h5, int level, const char* kind) {
  return h5.stem().string() + "_L" + std::to_string(level) + "_" + kind + ".xdmf";
}

std::vector<std::string> field_names(hid_t file, int level) {
  const auto group_path = level_path(level) + "/volume/fields";
  std::vector<std::string> names;
  if (!link_exists(file, group_path)) return names;
  Handle group(H5Gopen2(file, group_path.c_str(), H5P_DEFAULT), H5Gclose, "group " + group_path);
  H5G_info_t info{};
  check(H5Gget_info(group.get(), &info), "group info " + group_path);
  for (hsize_t i = 0; i < info.nlinks; ++i) {
    const auto size = H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, nullptr,
                                         0, H5P_DEFAULT);
    if (size < 0) throw H5Failure("field name in " + group_path);
    std::string name(static_cast<std::size_t>(size) + 1, '\0');
    H5Lget_name_by_idx(group.get(), ".", H5_INDEX_NAME, H5_ITER_INC, i, name.data(), name.size(),
                       H5P_DEFAULT);
    name.resize(static_cast<std::size_t>(size));
    names.push_back(name);
  }
  std::sort(names.begin(), names.end());
  return names;
}

// One mesh of a level ("volume" or "surface") as the XDMF sidecars describe it: points,
// cells, and the marker arrays whose lengths match them.
XdmfMesh describe_mesh(hid_t file, int level, const std::string& part, const std::string& cells,
                       const std::string& cell_markers, bool tetrahedra) {
  const std::string base = level_path(level) + "/" + part;
  XdmfMesh mesh;
  mesh.name = "level" + std::to_string(level) + "_" + part;
  mesh.points = base + "/points";
  mesh.cells = base + "/" + cells;
  mesh.tetrahedra = tetrahedra;
  mesh.num_points = dataset_rows(file, mesh.points);
  mesh.num_cells = dataset_rows(file, mesh.cells);
  if (dataset_rows(file, base + "/" + cell_markers) == mesh.num_cells) {
    mesh.attributes.push_back({cell_markers, base + "/" + cell_markers, true, true});
  }
  if (dataset_rows(file, base + "/vertex_markers") == mesh.num_points) {
    mesh.attributes.push_back({"vertex_markers", base + "/vertex_markers", false, true});
  }
  return mesh;
}

// Regenerates every XDMF sidecar from what the HDF5 file holds (sizes and fields), so the
// sidecars always describe the file as it is.
void write_sidecars(const std::filesystem::path& h5) {
  auto [file, levels] = open_unprobed(h5, H5F_ACC_RDONLY);
  const std::string reference = h5.filename().string();
  const auto folder = h5.parent_path();
  std::vector<XdmfMesh> all;
  for (int level = 0; level < levels; ++level) {
    XdmfMesh volume =
        describe_mesh(file.get(), level, "volume", "tetrahedra", "cell_markers", true);
    for (const auto& name : field_names(file.get(), level)) {
      volume.attributes.push_back(
          {name, level_path(level) + "/volume/fields/" + name, false, false});
    }
    XdmfMesh surface =
        describe_mesh(file.get(), level, "surface", "triangles", "face_markers", false);
    write_xdmf(folder / sidecar_name(h5, level, "volume"), reference, {volume}, false);
    write_xdmf(folder / sidecar_name(h5, level, "surface"), reference, {surface}, false);
    all.push_back(std::move(volume));
    all.push_back(std::move(surface));
  }
  write_xdmf(folder / (h5.stem().string() + ".xdmf"), reference, all, true);
}

// HDF5 files are built in memory (the core driver without a backing store) and their bytes
// written by write_file_atomically. libhdf5 1.10 cannot close a file whose flush failed:
// it stays open and H5_term_library crashed at exit after a full disk (issue 18). In
// memory nothing can fail that way, and the disk write gets the same checks, temporaries,
// signal cleanup and special-file handling as every other output.
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

std::vector<char> hierarchy_image(const std::filesystem::path& target, const Hierarchy& hierarchy) {
  Handle fapl = in_memory_access();
  Handle file(H5Fcreate(target.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose,
              "cannot create the HDF5 file");
  const hid_t root = file.get();
  write_string_attribute(root, "format", kHierarchyFormatName);
  write_array_attribute<int>(root, "format_version", {kHierarchyFormatVersion}, true);
  write_string_attribute(root, "length_unit", "angstrom");
  write_array_attribute<int>(root, "num_levels", {static_cast<int>(hierarchy.levels.size())}, true);
  std::vector<double> t0;
  for (const auto& level : hierarchy.levels) t0.push_back(level.t0);
  write_array_attribute(root, "t0", t0);
  write_string_attribute(root, "input_name", hierarchy.input_name);
  write_string_attribute(root, "input_sha256", hierarchy.input_checksum);
  write_string_attribute(root, "level_order", "level 0 is the finest");
  for (const auto& [key, value] : hierarchy.parameters) {
    write_string_attribute(root, kParameterPrefix + key, value);
  }
  for (std::size_t i = 0; i < hierarchy.levels.size(); ++i) {
    write_level(root, static_cast<int>(i), hierarchy.levels[i]);
  }
  for (const auto& transfer : hierarchy.transfers) {
    const auto base = transfer_path(transfer.coarse_level, transfer.fine_level);
    {
      Handle group = create_group(root, base);
      write_string_attribute(group.get(), "restriction", "transpose of prolongation");
      write_string_attribute(group.get(), "description",
                             "prolongation P (fine x coarse): u_fine = P u_coarse; rows sum to 1; "
                             "restriction R = P^T");
      write_array_attribute<int>(group.get(), "coarse_level", {transfer.coarse_level}, true);
      write_array_attribute<int>(group.get(), "fine_level", {transfer.fine_level}, true);
    }
    write_csr(root, base + "/volume", transfer.volume);
    write_csr(root, base + "/surface", transfer.surface);
  }
  return file_image(root);
}

herr_t collect_parameter(hid_t loc, const char* name, const H5A_info_t*, void* data) {
  const std::string attribute = name;
  const std::string prefix = kParameterPrefix;
  if (attribute.rfind(prefix, 0) == 0) {
    auto& parameters = *static_cast<std::map<std::string, std::string>*>(data);
    if (auto value = read_string_attribute(loc, attribute)) {
      parameters[attribute.substr(prefix.size())] = *value;
    }
  }
  return 0;
}

void validate_field_name(const std::string& name) {
  if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..") {
    throw Error("point field name \"" + name +
                "\" is not allowed (use a non-empty name without '/')");
  }
}

Hierarchy read_contents(const std::filesystem::path& path);

// --- containing libhdf5 ---------------------------------------------------------------------
// libhdf5 1.10 crashes (SIGSEGV in H5A__close from H5Aiterate2) or loops forever on some
// damaged files: 4 bytes changed in the metadata were enough (issue 18). No check of the
// file's structure ahead of libhdf5 can rule that out, so the first read of a file runs in
// a child process: everything a reader here will touch is read there once. If the child
// dies or runs out of time, the file is refused (InputError, exit code 3) and this process
// never hands the file to libhdf5; otherwise the real read repeats what is known to work.
// Costs one extra read of the file (docs/formats.md, "Damaged files").
void read_everything(const std::filesystem::path& path) {
  read_contents(path);
  auto [file, levels] = open_unprobed(path, H5F_ACC_RDONLY);
  for (int level = 0; level < levels; ++level)
    for (const auto& name : field_names(file.get(), level))
      read_dataset<double>(file.get(), level_path(level) + "/volume/fields/" + name, 0);
}

std::string probe_key(const std::filesystem::path& path) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  const auto time = std::filesystem::last_write_time(path, ec).time_since_epoch().count();
  return std::filesystem::absolute(path).string() + "|" + std::to_string(size) + "|" +
         std::to_string(time);
}

void probe_hierarchy(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw InputError(path.string(), "no such file");
  static std::mutex mutex;
  static std::set<std::string> probed;  // files this process has read safely already
  const std::string key = probe_key(path);
  {
    const std::lock_guard lock(mutex);
    if (probed.count(key)) return;
  }
  int channel[2];
  if (::pipe(channel) != 0) throw InputError(path.string(), "cannot start the reader");
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(channel[0]);
    ::close(channel[1]);
    throw InputError(path.string(), "cannot start the reader");
  }
  if (child == 0) {
    ::close(channel[0]);
    std::string message;
    int code = 0;
    try {
      read_everything(path);
    } catch (const std::exception& e) {
      message = e.what();
      code = 3;
    }
    if (!message.empty() && ::write(channel[1], message.data(), message.size()) < 0) code = 4;
    ::_exit(code);  // no atexit handlers, no HDF5 shutdown: just the verdict
  }
  ::close(channel[1]);
  // Generous: reading a 100 MB hierarchy takes about a second.
  const double seconds = 60.0 + static_cast<double>(std::filesystem::file_size(path)) / 1e7;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  std::string message;
  bool timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                          deadline - std::chrono::steady_clock::now())
                          .count();
    if (left <= 0) {
      timed_out = true;
      break;
    }
    pollfd fd{channel[0], POLLIN, 0};
    const int ready = ::poll(&fd, 1, static_cast<int>(std::min<long long>(left, 1000)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;
    char buffer[4096];
    const ssize_t n = ::read(channel[0], buffer, sizeof buffer);
    if (n <= 0) break;  // EOF: the child is done
    message.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(channel[0]);
  if (timed_out) ::kill(child, SIGKILL);
  int status = 0;
  while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  if (timed_out)
    throw InputError(path.string(), "damaged HDF5 file: reading it did not finish within " +
                                        std::to_string(static_cast<int>(seconds)) + " s");
  if (WIFSIGNALED(status))
    throw InputError(path.string(), "damaged HDF5 file: libhdf5 crashed reading it (signal " +
                                        std::to_string(WTERMSIG(status)) + ")");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    // The child's InputError already starts with the file name.
    const std::string prefix = path.string() + ": ";
    if (message.rfind(prefix, 0) == 0) message.erase(0, prefix.size());
    throw InputError(path.string(), message.empty() ? "damaged HDF5 file" : message);
  }
  const std::lock_guard lock(mutex);
  probed.insert(key);
}

std::pair<Handle, int> open_hierarchy(const std::filesystem::path& path, unsigned flags) {
  probe_hierarchy(path);
  return open_unprobed(path, flags);
}

}  // namespace

void write_hierarchy(const std::filesystem::path& path, const Hierarchy& hierarchy) {
  silence_hdf5();
  if (hierarchy.transfers.size() + 1 != hierarchy.levels.size() && !hierarchy.levels.empty()) {
    throw Error("hierarchy has " + std::to_string(hierarchy.levels.size()) + " levels but " +
                std::to_string(hierarchy.transfers.size()) + " transfer operators");
  }
  std::vector<char> image;
  try {
    image = hierarchy_image(path, hierarchy);
  } catch (const H5Failure& e) {
    throw OutputError(path.string() + ": HDF5: " + e.what());
  }
  write_image(path, image);
  try {
    write_sidecars(path);
  } catch (const H5Failure& e) {
    throw OutputError(path.string() + ": XDMF sidecars: " + e.what());
  }
}

Hierarchy read_hierarchy(const std::filesystem::path& path) {
  probe_hierarchy(path);
  return read_contents(path);
}

namespace {

Hierarchy read_contents(const std::filesystem::path& path) {
  auto [file, levels] = open_unprobed(path, H5F_ACC_RDONLY);
  Hierarchy hierarchy;
  try {
    const hid_t root = file.get();
    hierarchy.input_name = read_string_attribute(root, "input_name").value_or("");
    hierarchy.input_checksum = read_string_attribute(root, "input_sha256").value_or("");
    hsize_t index = 0;
    check(H5Aiterate2(root, H5_INDEX_NAME, H5_ITER_INC, &index, collect_parameter,
                      &hierarchy.parameters),
          "parameters");
    for (int level = 0; level < levels; ++level)
      hierarchy.levels.push_back(read_level(root, level));
    for (int fine = 0; fine + 1 < levels; ++fine) {
      LevelTransfer transfer;
      transfer.coarse_level = fine + 1;
      transfer.fine_level = fine;
      const auto base = transfer_path(fine + 1, fine);
      transfer.volume = read_csr(root, base + "/volume");
      transfer.surface = read_csr(root, base + "/surface");
      const auto& fine_level = hierarchy.levels[static_cast<std::size_t>(fine)];
      const auto& coarse_level = hierarchy.levels[static_cast<std::size_t>(fine + 1)];
      if (transfer.volume.rows() != static_cast<Eigen::Index>(fine_level.volume.points.size()) ||
          transfer.volume.cols() != static_cast<Eigen::Index>(coarse_level.volume.points.size()) ||
          transfer.surface.rows() != static_cast<Eigen::Index>(fine_level.surface.points.size()) ||
          transfer.surface.cols() !=
              static_cast<Eigen::Index>(coarse_level.surface.points.size())) {
        throw H5Failure(base + ": matrix shape does not match the level sizes");
      }
      for (const SparseMatrix* m : {&transfer.volume, &transfer.surface})
        for (Eigen::Index k = 0; k < m->nonZeros(); ++k)
          if (!std::isfinite(m->valuePtr()[k]))
            throw H5Failure(base + ": a prolongation weight is not finite");
      const auto& provenance = coarse_level.surface_provenance;
      check_length(provenance.size(), coarse_level.surface.points.size(),
                   level_path(fine + 1) + "/surface/provenance", true);
      for (int p : provenance)
        if (p < 0 || static_cast<std::size_t>(p) >= fine_level.surface.points.size())
          throw H5Failure(level_path(fine + 1) + "/surface/provenance: vertex " +
                          std::to_string(p) + " out of range");
      hierarchy.transfers.push_back(std::move(transfer));
    }
  } catch (const H5Failure& e) {
    throw InputError(path.string(), std::string("damaged molmesh hierarchy: ") + e.what());
  }
  return hierarchy;
}

}  // namespace

void write_point_field(const std::filesystem::path& h5, int level, const std::string& name,
                       std::span<const double> values) {
  validate_field_name(name);
  {
    auto [file, levels] = open_hierarchy(h5, H5F_ACC_RDONLY);
    if (level < 0 || level >= levels) {
      throw InputError(h5.string(), "has no level " + std::to_string(level) + " (levels 0.." +
                                        std::to_string(levels - 1) + ")");
    }
    std::size_t points = 0;
    try {
      points = dataset_rows(file.get(), level_path(level) + "/volume/points");
    } catch (const H5Failure& e) {
      throw InputError(h5.string(), e.what());
    }
    if (points != values.size()) {
      throw Error("point field \"" + name + "\" has " + std::to_string(values.size()) +
                  " values but level " + std::to_string(level) + " has " + std::to_string(points) +
                  " volume vertices");
    }
  }
  std::vector<char> image;
  try {
    // The whole file is read into memory, edited there and written back atomically.
    Handle fapl = in_memory_access();
    Handle file(H5Fopen(h5.c_str(), H5F_ACC_RDWR, fapl.get()), H5Fclose, "cannot open for writing");
    const auto dataset = level_path(level) + "/volume/fields/" + name;
    if (link_exists(file.get(), dataset)) {
      check(H5Ldelete(file.get(), dataset.c_str(), H5P_DEFAULT), "cannot replace " + dataset);
    }
    write_dataset(file.get(), dataset, values.data(), values.size(), 0);
    image = file_image(file.get());
  } catch (const H5Failure& e) {
    throw OutputError(h5.string() + ": HDF5: " + e.what());
  }
  write_image(h5, image);
  try {
    write_sidecars(h5);
  } catch (const H5Failure& e) {
    throw OutputError(h5.string() + ": XDMF sidecars: " + e.what());
  }
}

std::vector<double> read_point_field(const std::filesystem::path& h5, int level,
                                     const std::string& name) {
  auto [file, levels] = open_hierarchy(h5, H5F_ACC_RDONLY);
  const auto dataset = level_path(level) + "/volume/fields/" + name;
  if (level < 0 || level >= levels || !link_exists(file.get(), dataset)) {
    throw InputError(h5.string(),
                     "has no point field \"" + name + "\" on level " + std::to_string(level));
  }
  try {
    return read_dataset<double>(file.get(), dataset, 0);
  } catch (const H5Failure& e) {
    throw InputError(h5.string(), e.what());
  }
}

std::vector<std::string> point_field_names(const std::filesystem::path& h5, int level) {
  auto [file, levels] = open_hierarchy(h5, H5F_ACC_RDONLY);
  if (level < 0 || level >= levels) {
    throw InputError(h5.string(), "has no level " + std::to_string(level));
  }
  try {
    return field_names(file.get(), level);
  } catch (const H5Failure& e) {
    throw InputError(h5.string(), e.what());
  }
}

}  // namespace molmesh
