add_library(molmesh_warnings INTERFACE)
target_compile_options(molmesh_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion>
  # GCC 12's -Wrestrict misfires inside libstdc++'s own std::string concatenation at -O2
  # (GCC bug 105329, fixed in 13); every report it gave here pointed into char_traits.h.
  # -Warray-bounds and -Wstringop-overflow likewise, on the same concatenations ("literal" +
  # std::string, inlined std::string::insert): with the precompiled headers GCC 12 reported
  # a memcpy "pointer overflow" / "bound exceeds maximum object size" inside char_traits.h
  # at seven of them (silencing one warning made the same call report the other). clang's
  # -Warray-bounds stays on in the sanitizer builds, beside ASan itself.
  $<$<AND:$<CXX_COMPILER_ID:GNU>,$<VERSION_LESS:$<CXX_COMPILER_VERSION>,13>>:-Wno-restrict -Wno-array-bounds -Wno-stringop-overflow>)

# Adds one static library per pipeline stage from the sources in its folder, so each
# stage is usable alone and a newcomer finds it by folder name. `SOURCES a.cpp b.cpp`
# (names within the folder) takes only those files, for a folder split into libraries.
function(molmesh_stage_library name folder)
  cmake_parse_arguments(PARSE_ARGV 2 _arg "" "" "SOURCES")
  if(_arg_SOURCES)
    list(TRANSFORM _arg_SOURCES PREPEND ${folder}/ OUTPUT_VARIABLE _sources)
  else()
    file(GLOB _sources CONFIGURE_DEPENDS ${folder}/*.cpp)
  endif()
  if(NOT _sources)
    # A stage whose code is all in headers (or not written yet) still gets a real archive.
    set(_empty ${CMAKE_CURRENT_BINARY_DIR}/molmesh_${name}_empty.cpp)
    file(WRITE ${_empty} "// generated: stage ${name} has no compiled sources\n")
    set(_sources ${_empty})
  endif()
  add_library(molmesh_${name} STATIC ${_sources})
  add_library(molmesh::${name} ALIAS molmesh_${name})
  set_target_properties(molmesh_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${name})
  target_include_directories(molmesh_${name} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/lib>
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_link_libraries(molmesh_${name} PRIVATE $<BUILD_INTERFACE:molmesh_warnings>)
  molmesh_library_precompiled_headers(molmesh_${name})
  set_property(GLOBAL APPEND PROPERTY MOLMESH_EXPORTED_TARGETS molmesh_${name})
endfunction()
