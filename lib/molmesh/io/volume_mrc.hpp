#pragma once
// MRC2014 / CCP4 density maps (.mrc, .map, .ccp4). Reading honours the axis order
// (MAPC/MAPR/MAPS), the voxel size (cell length / MX,MY,MZ), the origin (header words
// 50-52, or NXSTART/NYSTART/NZSTART x voxel size when those are all zero), the byte order
// (MACHST, or the plausibility of MODE when MACHST is unset), an extended header (NSYMBT),
// and modes 0 (int8), 1 (int16), 2 (float32) and 6 (uint16). Writing: mode 2, x fastest,
// little endian, MRC2014 (NVERSION 20140).
#include <ostream>
#include <string>

#include "molmesh/volume/grid.hpp"

namespace molmesh {

Grid parse_mrc(const std::string& bytes, const std::string& name);
void write_mrc(std::ostream& out, const Grid& grid);

}  // namespace molmesh
