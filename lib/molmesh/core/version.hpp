#pragma once
// The molmesh version, from project(VERSION) in the top-level CMakeLists.txt (the one
// place it is written): `molmesh --version` and the provenance of hierarchy files.

namespace molmesh {

const char* version();

}  // namespace molmesh
