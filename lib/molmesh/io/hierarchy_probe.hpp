#pragma once
// Containing libhdf5 on damaged files (docs/formats.md, "Damaged files"): the first read of
// a hierarchy file in this process runs in a child process. Internal to io_hierarchy.
#include <filesystem>
#include <utility>

#include "molmesh/io/hdf5_file.hpp"

namespace molmesh::hierarchy_file {

// Reads everything a reader here will touch once in a child process, unless this process
// has read the same file (path, size, time) safely already. Throws InputError when the
// file is missing, the child crashes, runs out of time or refuses the file.
void probe_hierarchy(const std::filesystem::path& path);

// probe_hierarchy, then open_unprobed (hierarchy_layout.hpp).
std::pair<hdf5::Handle, int> open_hierarchy(const std::filesystem::path& path, unsigned flags);

}  // namespace molmesh::hierarchy_file
