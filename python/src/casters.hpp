#pragma once
// The type casters of the module, in one place. pybind11 picks a caster per C++ type at
// compile time, so every translation unit must see the same ones: a file that converts a
// std::filesystem::path without <pybind11/stl/filesystem.h> instantiates the generic caster
// under the same symbol names as the files that have it, and the linker keeps one of the two
// (an ODR violation; AddressSanitizer saw the path caster write past the 24-byte generic one
// on the stack). Every .cpp of the module includes this header instead of the pieces.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>
