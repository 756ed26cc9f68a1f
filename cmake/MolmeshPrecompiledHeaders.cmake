# Precompiled headers (docs/testing.md, "Build time"). On 2 cores most of a build is the
# compiler re-reading the standard library, Eigen and (in tests) GoogleTest for every one of
# ~350 translation units, so each kind of target compiles those headers once, in a small
# host target, and every other target of that kind reuses the result (REUSE_FROM).
#
# A GCC precompiled header is only used by a translation unit compiled with the same code
# generation flags, so there is one host per kind: the static libraries (-fPIC) and the
# test executables (-fPIE). A unit whose flags differ falls back to the plain headers and
# says so (-Winvalid-pch), so a mismatch costs time, never correctness.
option(MOLMESH_PRECOMPILE_HEADERS "Precompile the standard library, Eigen and GoogleTest headers" ON)

# What nearly every translation unit includes (counted over lib/, solvers/, tests/).
set(MOLMESH_PCH_COMMON
  <algorithm> <array> <cmath> <cstddef> <cstdint> <filesystem> <fstream> <functional>
  <limits> <map> <memory> <optional> <span> <string> <string_view> <utility> <vector>
  <Eigen/Core> <Eigen/Geometry> <Eigen/Sparse> <tbb/parallel_for.h>)

# Makes `target` reuse the precompiled headers of `host`, creating the host on first use:
# a target of `kind` (LIBRARY: a static library, EXECUTABLE: a program) that links
# LIBRARIES (for their include paths) and precompiles MOLMESH_PCH_COMMON plus HEADERS.
# Every target reusing one host must be of its kind and compiled with the same flags.
function(molmesh_reuse_precompiled_headers target host kind)
  cmake_parse_arguments(PARSE_ARGV 3 _arg "" "" "LIBRARIES;HEADERS")
  if(NOT MOLMESH_PRECOMPILE_HEADERS)
    return()
  endif()
  if(NOT TARGET ${host})
    set(_source ${PROJECT_BINARY_DIR}/precompiled/${host}.cpp)
    if(kind STREQUAL "EXECUTABLE")
      file(WRITE ${_source} "// generated: host of precompiled headers\nint main() { return 0; }\n")
      add_executable(${host} ${_source})
    elseif(kind STREQUAL "LIBRARY")
      file(WRITE ${_source} "// generated: host of precompiled headers\n")
      add_library(${host} STATIC ${_source})
    else()
      message(FATAL_ERROR "molmesh_reuse_precompiled_headers: kind is LIBRARY or EXECUTABLE")
    endif()
    target_link_libraries(${host} PRIVATE molmesh_warnings ${_arg_LIBRARIES})
    target_precompile_headers(${host} PRIVATE ${MOLMESH_PCH_COMMON} ${_arg_HEADERS})
  endif()
  target_precompile_headers(${target} REUSE_FROM ${host})
endfunction()

# The host for the stage libraries, the solvers and the test support libraries.
function(molmesh_library_precompiled_headers target)
  molmesh_reuse_precompiled_headers(${target} molmesh_library_pch LIBRARY
    LIBRARIES Eigen3::Eigen TBB::tbb)
endfunction()

