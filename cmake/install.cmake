# `cmake --install BUILD --prefix PREFIX` (docs/library.md): the glintlab command, the shared
# library with its interface headers, the shaders (to read: the binaries embed their own copy) and
# the package files, so that a program finds it with find_package(glintlab) and links one target,
# glintlab::glintlab.
include(CMakePackageConfigHelpers)

install(TARGETS glintlab RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS glintlab_library EXPORT glintlabTargets
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/glintlab DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/ DESTINATION ${CMAKE_INSTALL_DATADIR}/glintlab/shaders)

set(glintlab_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/glintlab)
install(EXPORT glintlabTargets NAMESPACE glintlab:: DESTINATION ${glintlab_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/glintlabConfig.cmake.in
  ${PROJECT_BINARY_DIR}/glintlabConfig.cmake INSTALL_DESTINATION ${glintlab_cmake_dir} PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/glintlabConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/glintlabConfig.cmake ${PROJECT_BINARY_DIR}/glintlabConfigVersion.cmake
  DESTINATION ${glintlab_cmake_dir})
