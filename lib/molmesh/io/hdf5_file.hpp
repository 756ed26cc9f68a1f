#pragma once
// The small part of libhdf5 the hierarchy file uses, behind RAII handles: datasets (chunked,
// shuffled, deflated; no modification times, so the same data gives the same bytes),
// attributes, and files built in memory and written atomically. Internal to io_hierarchy.
#include <hdf5.h>

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh::hdf5 {

// Internal failure of one HDF5 call; the public entry points turn it into InputError or
// OutputError naming the file.
struct H5Failure : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The library never prints: silence HDF5's default error-stack dump on stderr.
void silence_hdf5();

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

void check(herr_t status, const std::string& what);

// Whether every link along `path` exists (H5Lexists alone needs the parents to exist).
bool link_exists(hid_t loc, const std::string& path);

// Creates the group and its missing parents.
Handle create_group(hid_t loc, const std::string& path);

// --- datasets (T: double, int, std::int64_t) ------------------------------------------------

// rows x cols (cols = 0: a 1-D dataset of `rows` values); missing parent groups are created.
template <class T>
void write_dataset(hid_t loc, const std::string& name, const T* data, std::size_t rows,
                   std::size_t cols);

template <class T>
void write_vector(hid_t loc, const std::string& name, const std::vector<T>& values) {
  write_dataset(loc, name, values.data(), values.size(), 0);
}

void write_points(hid_t loc, const std::string& name, const std::vector<Vec3>& points);

template <std::size_t N>
void write_cells(hid_t loc, const std::string& name, const std::vector<std::array<int, N>>& cells) {
  write_dataset(loc, name, cells.empty() ? nullptr : cells.front().data(), cells.size(), N);
}

// Reads a dataset as T; `cols` 0 means 1-D. Returns the values and the row count. Refuses a
// missing dataset, the wrong shape, and more rows than the file could hold.
template <class T>
std::vector<T> read_dataset(hid_t loc, const std::string& name, std::size_t cols,
                            std::size_t* rows_out = nullptr);

std::vector<Vec3> read_points(hid_t loc, const std::string& name);

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

// The first dimension of a dataset, without reading it.
std::size_t dataset_rows(hid_t loc, const std::string& name);

// --- attributes -----------------------------------------------------------------------------

// A UTF-8 variable-length string, replacing one of the same name.
void write_string_attribute(hid_t loc, const std::string& name, const std::string& value);

// A 1-D array, or (scalar) one value.
template <class T>
void write_array_attribute(hid_t loc, const std::string& name, const std::vector<T>& values,
                           bool scalar = false);

// nullopt when absent or not a string.
std::optional<std::string> read_string_attribute(hid_t loc, const std::string& name);

template <class T>
std::vector<T> read_array_attribute(hid_t loc, const std::string& name);

// --- files built in memory ------------------------------------------------------------------

// HDF5 files are built in memory (the core driver without a backing store) and their bytes
// written by write_file_atomically. libhdf5 1.10 cannot close a file whose flush failed:
// it stays open and H5_term_library crashed at exit after a full disk (issue 18). In
// memory nothing can fail that way, and the disk write gets the same checks, temporaries,
// signal cleanup and special-file handling as every other output.
Handle in_memory_access();

// The bytes of an open in-memory file.
std::vector<char> file_image(hid_t file);

// Writes the bytes atomically (temporary file + rename).
void write_image(const std::filesystem::path& path, const std::vector<char>& image);

}  // namespace molmesh::hdf5
