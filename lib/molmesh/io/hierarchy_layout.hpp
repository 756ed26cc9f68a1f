#pragma once
// The layout of a hierarchy HDF5 file (docs/formats.md, "Hierarchy HDF5"): where each level,
// transfer and point field lives, and the whole hierarchy written to and read from it.
// Internal to io_hierarchy; the public API is hierarchy_hdf5.hpp.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "molmesh/hierarchy/hierarchy.hpp"
#include "molmesh/io/hdf5_file.hpp"

namespace molmesh::hierarchy_file {

std::string level_path(int level);
std::string transfer_path(int coarse, int fine);
// A point field of a level's volume: /levels/<level>/volume/fields/<name>.
std::string field_path(int level, const std::string& name);

// Opens an existing file and checks it is a molmesh hierarchy; returns it and its level count.
// Only for files already probed (probe_hierarchy) or just written by us. Throws InputError.
std::pair<hdf5::Handle, int> open_unprobed(const std::filesystem::path& path, unsigned flags);

// The bytes of the HDF5 file holding `hierarchy` (built in memory; `target` only names it).
std::vector<char> hierarchy_image(const std::filesystem::path& target, const Hierarchy& hierarchy);

// Reads and validates (hierarchy_validate.hpp) the whole hierarchy of an already probed
// file. Throws InputError.
Hierarchy read_contents(const std::filesystem::path& path);

// Names of the point fields stored for `level` (sorted).
std::vector<std::string> field_names(hid_t file, int level);

}  // namespace molmesh::hierarchy_file
