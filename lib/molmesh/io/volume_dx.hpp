#pragma once
// OpenDX scalar fields in the layout APBS writes and reads: "object 1 class gridpositions
// counts nx ny nz", "origin", three "delta" lines (axis-aligned), "object 2 class
// gridconnections", "object 3 class array type double rank 0 items N data follows", the N
// values with z varying fastest (then y, then x), then attribute/field lines.
#include <ostream>
#include <string>
#include <string_view>

#include "molmesh/volume/grid.hpp"

namespace molmesh {

Grid parse_dx(std::string_view text, const std::string& name);
void write_dx(std::ostream& out, const Grid& grid);

}  // namespace molmesh
