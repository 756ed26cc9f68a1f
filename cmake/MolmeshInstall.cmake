include(CMakePackageConfigHelpers)
get_property(_targets GLOBAL PROPERTY MOLMESH_EXPORTED_TARGETS)
install(TARGETS ${_targets} EXPORT molmeshTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
# The private helper targets are header/flag-only; export them so the static archives link.
install(TARGETS molmesh_warnings molmesh_tetgen molmesh_gemmi EXPORT molmeshTargets)
install(EXPORT molmeshTargets NAMESPACE molmesh:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/molmesh)
configure_package_config_file(cmake/molmeshConfig.cmake.in
  ${CMAKE_CURRENT_BINARY_DIR}/molmeshConfig.cmake
  INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/molmesh)
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/molmeshConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/molmeshConfig.cmake
  ${CMAKE_CURRENT_BINARY_DIR}/molmeshConfigVersion.cmake
  DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/molmesh)
