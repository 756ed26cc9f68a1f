#pragma once
// Scalar volumes, chosen by extension: .dx (OpenDX scalar field in the layout APBS writes
// and reads) and .mrc/.map/.ccp4 (MRC2014 / CCP4 maps). Details in docs/formats.md.
#include <filesystem>

#include "molmesh/volume/grid.hpp"

namespace molmesh {

// Throws InputError (file:line: what) for missing files and malformed content.
Grid read_volume(const std::filesystem::path& path);

// Atomic. OpenDX is written in APBS's layout; MRC as mode 2 (float32) with the origin in
// header words 50-52 and cell dimensions = voxel size x samples.
void write_volume(const std::filesystem::path& path, const Grid& grid);

bool is_volume_path(const std::filesystem::path& path);

}  // namespace molmesh
