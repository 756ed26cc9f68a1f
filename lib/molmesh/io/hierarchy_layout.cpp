#include "molmesh/io/hierarchy_layout.hpp"

#include <algorithm>
#include <cstdint>
#include <map>
#include <optional>

#include "molmesh/core/error.hpp"
#include "molmesh/io/hierarchy_hdf5.hpp"
#include "molmesh/io/hierarchy_validate.hpp"

namespace molmesh::hierarchy_file {

using namespace hdf5;

namespace {

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
  validate_csr(group_path, shape, data, indices, indptr64);
  std::vector<int> indptr(indptr64.size());
  for (std::size_t i = 0; i < indptr.size(); ++i) indptr[i] = static_cast<int>(indptr64[i]);
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

  validate_level(level, base);
  return level;
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

}  // namespace

std::string level_path(int level) { return "/levels/" + std::to_string(level); }
std::string transfer_path(int coarse, int fine) {
  return "/transfer/" + std::to_string(coarse) + "_to_" + std::to_string(fine);
}
std::string field_path(int level, const std::string& name) {
  return level_path(level) + "/volume/fields/" + name;
}

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
      validate_transfer(transfer, fine_level, coarse_level, fine, base);
      hierarchy.transfers.push_back(std::move(transfer));
    }
  } catch (const H5Failure& e) {
    throw InputError(path.string(), std::string("damaged molmesh hierarchy: ") + e.what());
  }
  return hierarchy;
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

}  // namespace molmesh::hierarchy_file
