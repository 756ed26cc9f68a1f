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

# Public headers include only public headers: every quoted include of an installed header,
# and every <molmesh/...> or <solvers/...> one, resolves inside the installed include tree
# (next to the header, under include/ or, for the solvers' "solvers/..." form, under
# include/molmesh/), so no public header includes an internal one (internal headers stay in
# the source tree, lib/CMakeLists.txt). Lines are matched with the preprocessor's freedom
# (indentation, "# include") so a guarded or indented include is checked too.
# Their angle-bracket includes are the standard library's or those of the dependencies that
# are part of the API (Eigen, nlohmann/json): TetGen, HDF5, gemmi, Boost, TBB, OpenSSL and
# zlib are linked privately, and a header that needs one (TetGen's tetgenio in
# tetmesh/tetgen_output.hpp) is internal. Standard headers are the names without "/" or ".".
set(include_line "^[ \t]*#[ \t]*include[ \t]*")
set(api_dependencies "^(Eigen|nlohmann)/")
file(GLOB_RECURSE installed RELATIVE ${prefix}/include ${prefix}/include/molmesh/*.hpp)
set(problems "")
foreach(header ${installed})
  get_filename_component(folder ${prefix}/include/${header} DIRECTORY)
  file(STRINGS ${prefix}/include/${header} quoted REGEX "${include_line}\"")
  file(STRINGS ${prefix}/include/${header} bracketed REGEX "${include_line}<")
  foreach(line ${quoted})
    string(REGEX REPLACE "${include_line}\"([^\"]+)\".*" "\\1" included "${line}")
    if(NOT EXISTS ${folder}/${included} AND NOT EXISTS ${prefix}/include/${included}
        AND NOT EXISTS ${prefix}/include/molmesh/${included})
      string(APPEND problems "  ${header} includes \"${included}\", which is not installed\n")
    endif()
  endforeach()
  foreach(line ${bracketed})
    string(REGEX REPLACE "${include_line}<([^>]+)>.*" "\\1" included "${line}")
    if(included MATCHES "^(molmesh|solvers)/")
      if(NOT EXISTS ${prefix}/include/${included} AND NOT EXISTS ${prefix}/include/molmesh/${included})
        string(APPEND problems "  ${header} includes <${included}>, which is not installed\n")
      endif()
    elseif(included MATCHES "[/.]" AND NOT included MATCHES "${api_dependencies}")
      string(APPEND problems
        "  ${header} includes <${included}>, a header of a private dependency\n")
    endif()
  endforeach()
endforeach()
if(problems)
  message(FATAL_ERROR "installed headers that only build inside the molmesh tree "
    "(add them to MOLMESH_INTERNAL_HEADERS, lib/CMakeLists.txt, or drop the include):\n${problems}")
endif()
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
