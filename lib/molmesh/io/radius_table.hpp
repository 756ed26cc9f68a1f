#pragma once
// User radius tables (--radii FILE). One entry per line, '#' starts a comment:
//   RESNAME ATOMNAME radius   e.g. "ARG NH1 1.55", "* CA 1.90", "HEM * 1.80"
//   ELEMENT radius            e.g. "FE 1.40", "* 1.80" (any atom not matched otherwise)
// Names are case-insensitive; radii are in Å and must be finite and >= 0.
#include <filesystem>

#include "molmesh/atoms/radius_table.hpp"

namespace molmesh {

// Throws InputError (file:line: what) for malformed entries, duplicates and empty tables.
RadiusTable read_radius_table(const std::filesystem::path& path);

}  // namespace molmesh
