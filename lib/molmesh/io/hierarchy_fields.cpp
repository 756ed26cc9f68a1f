// The point fields of hierarchy_hdf5.hpp: one dataset per field under a level's volume
// (docs/formats.md, "Hierarchy HDF5").
#include <span>
#include <string>
#include <vector>

#include "molmesh/core/error.hpp"
#include "molmesh/io/hdf5_file.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/io/hierarchy_layout.hpp"
#include "molmesh/io/hierarchy_probe.hpp"
#include "molmesh/io/hierarchy_xdmf.hpp"

namespace molmesh {

using namespace hdf5;
using namespace hierarchy_file;

namespace {

void validate_field_name(const std::string& name) {
  if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..") {
    throw Error("point field name \"" + name +
                "\" is not allowed (use a non-empty name without '/')");
  }
}

}  // namespace

void write_point_fields(const std::filesystem::path& h5, int level,
                        std::span<const PointFieldView> fields) {
  if (fields.empty()) return;
  for (const PointFieldView& field : fields) validate_field_name(field.name);
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
    // Every field is checked before the file is touched, so a bad one stores none.
    for (const PointFieldView& field : fields) {
      if (points != field.values.size()) {
        throw Error("point field \"" + field.name + "\" has " +
                    std::to_string(field.values.size()) + " values but level " +
                    std::to_string(level) + " has " + std::to_string(points) + " volume vertices");
      }
    }
  }
  std::vector<char> image;
  try {
    // The whole file is read into memory, edited there and written back atomically, once
    // for all the fields.
    Handle fapl = in_memory_access();
    Handle file(H5Fopen(h5.c_str(), H5F_ACC_RDWR, fapl.get()), H5Fclose, "cannot open for writing");
    for (const PointFieldView& field : fields) {
      const auto dataset = field_path(level, field.name);
      if (link_exists(file.get(), dataset)) {
        check(H5Ldelete(file.get(), dataset.c_str(), H5P_DEFAULT), "cannot replace " + dataset);
      }
      write_dataset(file.get(), dataset, field.values.data(), field.values.size(), 0);
    }
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

void write_point_field(const std::filesystem::path& h5, int level, const std::string& name,
                       std::span<const double> values) {
  const PointFieldView field{name, values};
  write_point_fields(h5, level, std::span<const PointFieldView>(&field, 1));
}

std::vector<double> read_point_field(const std::filesystem::path& h5, int level,
                                     const std::string& name) {
  auto [file, levels] = open_hierarchy(h5, H5F_ACC_RDONLY);
  const auto dataset = field_path(level, name);
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
