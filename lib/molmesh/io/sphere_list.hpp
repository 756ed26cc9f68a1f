#pragma once
// Sphere lists (keep-spheres that forbid coarsening, active-site spheres for markers):
// one sphere per line, "x y z r" in Å, separated by blanks or commas; '#' starts a comment;
// blank lines are ignored.
#include <filesystem>
#include <vector>

#include "molmesh/core/geometry.hpp"

namespace molmesh {

// Throws InputError (file:line: what) for malformed lines, non-finite numbers, negative
// radii and files without any sphere.
std::vector<Sphere> read_spheres(const std::filesystem::path& path);

}  // namespace molmesh
