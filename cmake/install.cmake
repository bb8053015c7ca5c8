# Installs headers, the library, the CLI and a CMake package so that downstream projects can
#   find_package(bimdf REQUIRED)  target_link_libraries(app PRIVATE bimdf::bimdf)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS bimdf EXPORT bimdfTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/bimdf DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(FILES ${PROJECT_BINARY_DIR}/include/bimdf/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/bimdf)
if(BIMDF_BUILD_CLI)
  install(TARGETS bimdf_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

set(BIMDF_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/bimdf)
install(EXPORT bimdfTargets NAMESPACE bimdf:: DESTINATION ${BIMDF_CMAKE_DIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/bimdfConfig.cmake.in
  ${PROJECT_BINARY_DIR}/bimdfConfig.cmake INSTALL_DESTINATION ${BIMDF_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/bimdfConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/bimdfConfig.cmake ${PROJECT_BINARY_DIR}/bimdfConfigVersion.cmake
  DESTINATION ${BIMDF_CMAKE_DIR})
