# CTest driver (tests/CMakeLists.txt, test "package_consumer"): installs the build tree into
# a fresh prefix, checks the header layout, and builds and runs two consumers that find the
# package with find_package(molmesh) (tests/package/consumer). Variables: BUILD_DIR,
# SOURCE_DIR, WORK, OFF, CXX (the compiler of the build), optionally CXX_LAUNCHER and
# LINKER_FLAGS (the build's CMAKE_EXE_LINKER_FLAGS: a sanitizer build's libraries need its
# runtime, tools/build.sh).
file(REMOVE_RECURSE ${WORK})
set(prefix ${WORK}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
  RESULT_VARIABLE status OUTPUT_QUIET)
if(status)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()

# Every header goes under include/molmesh/; nothing else lands in include/.
file(GLOB top RELATIVE ${prefix}/include ${prefix}/include/*)
if(NOT top STREQUAL "molmesh")
  message(FATAL_ERROR "include/ holds '${top}', expected only 'molmesh'")
endif()
foreach(header molmesh/io/surface_mesh_io.hpp molmesh/geometry/predicates.hpp
    molmesh/solvers/fem/point_locator.hpp)
  if(NOT EXISTS ${prefix}/include/${header})
    message(FATAL_ERROR "include/${header} was not installed")
  endif()
endforeach()

# Public headers include only public headers: every "molmesh/..." include of an installed
# header is installed too (internal headers stay in the source tree, lib/CMakeLists.txt).
file(GLOB_RECURSE installed RELATIVE ${prefix}/include ${prefix}/include/molmesh/*.hpp)
foreach(header ${installed})
  file(STRINGS ${prefix}/include/${header} includes REGEX "^#include \"(molmesh|solvers)/")
  foreach(line ${includes})
    string(REGEX REPLACE "^#include \"([^\"]+)\".*" "\\1" included "${line}")
    if(NOT EXISTS ${prefix}/include/${included} AND NOT EXISTS ${prefix}/include/molmesh/${included})
      message(FATAL_ERROR "installed ${header} includes ${included}, which is not installed")
    endif()
  endforeach()
endforeach()
if(EXISTS ${prefix}/include/molmesh/processing/halfedge_mesh.hpp)
  message(FATAL_ERROR "internal header processing/halfedge_mesh.hpp was installed")
endif()

set(launcher "")
if(CXX_LAUNCHER)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CXX_LAUNCHER})
endif()
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK}/build
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CXX} ${launcher}
  "-DCMAKE_EXE_LINKER_FLAGS=${LINKER_FLAGS}"
  RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(status)
  message(FATAL_ERROR "configuring the consumer failed:\n${log}")
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${WORK}/build
  RESULT_VARIABLE status OUTPUT_VARIABLE log ERROR_VARIABLE log)
if(status)
  message(FATAL_ERROR "building the consumer failed:\n${log}")
endif()
execute_process(COMMAND ${WORK}/build/read_mesh ${OFF}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(status OR NOT out MATCHES "^4 vertices, 4 triangles, volume 0\\.166667")
  message(FATAL_ERROR "read_mesh printed (exit ${status}):\n${out}")
endif()
execute_process(COMMAND ${WORK}/build/locate_point
  RESULT_VARIABLE status OUTPUT_VARIABLE out2 ERROR_VARIABLE out2)
if(status OR NOT out2 MATCHES "^centroid in tetrahedron 0")
  message(FATAL_ERROR "locate_point printed (exit ${status}):\n${out2}")
endif()
# The mesh reader links neither HDF5 nor OpenSSL (io is split: lib/CMakeLists.txt).
execute_process(COMMAND ldd ${WORK}/build/read_mesh OUTPUT_VARIABLE libs RESULT_VARIABLE status)
if(status)
  message(FATAL_ERROR "ldd read_mesh failed")
endif()
if(libs MATCHES "libhdf5|libcrypto")
  message(FATAL_ERROR "read_mesh links HDF5 or OpenSSL:\n${libs}")
endif()
message(STATUS "consumer: ${out}${out2}")
