# Every dependency comes from Debian packages; nothing is downloaded at build time.
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(Boost 1.74 REQUIRED COMPONENTS graph)
find_package(HDF5 REQUIRED COMPONENTS C)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(CLI11 REQUIRED)
find_package(ZLIB REQUIRED)

# Debian's libtet1.5-dev ships a header and a shared library but no CMake config.
find_path(TETGEN_INCLUDE_DIR tetgen.h REQUIRED)
find_library(TETGEN_LIBRARY NAMES tet REQUIRED)
if(NOT TARGET molmesh_tetgen)
  add_library(molmesh_tetgen INTERFACE)
  target_include_directories(molmesh_tetgen SYSTEM INTERFACE ${TETGEN_INCLUDE_DIR})
  # tetgen.h switches between its library and program builds with TETLIBRARY.
  target_compile_definitions(molmesh_tetgen INTERFACE TETLIBRARY)
  target_link_libraries(molmesh_tetgen INTERFACE ${TETGEN_LIBRARY})
endif()

# gemmi-dev is header-only on Debian 12 (plus libgemmi_cpp is not packaged), with a
# zlib-backed gz reader.
find_path(GEMMI_INCLUDE_DIR gemmi/mmread.hpp REQUIRED)
if(NOT TARGET molmesh_gemmi)
  add_library(molmesh_gemmi INTERFACE)
  target_include_directories(molmesh_gemmi SYSTEM INTERFACE ${GEMMI_INCLUDE_DIR})
  target_link_libraries(molmesh_gemmi INTERFACE ZLIB::ZLIB)
endif()
