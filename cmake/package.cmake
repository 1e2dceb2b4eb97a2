# Install rules and the CMake package: `cmake --install build --prefix P` puts the public headers,
# the libraries and lib/cmake/dyop/ (dyopConfig.cmake, dyopConfigVersion.cmake, the exported
# targets dyop::dyop, dyop::box2d_bridge, dyop::box2d_grounds and, built with GEOS,
# dyop::box2d_outlines) under P, so that a project
# finds them with find_package(dyop CONFIG REQUIRED), and the licence in share/doc/dyop/ (a program that ships the
# libraries must carry it: MIT). Included by the top-level CMakeLists.txt (DYOP_INSTALL).
include(CMakePackageConfigHelpers)

set(DYOP_PACKAGE_TARGETS dyop)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/dyop/include/ ${PROJECT_BINARY_DIR}/dyop/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
if(DYOP_WITH_BOX2D)
  list(APPEND DYOP_PACKAGE_TARGETS dyop_box2d_bridge dyop_box2d_grounds)
  if(TARGET dyop_box2d_outlines)
    list(APPEND DYOP_PACKAGE_TARGETS dyop_box2d_outlines)
  endif()
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/box2d_bridge/include/
                    ${PROJECT_SOURCE_DIR}/box2d_grounds/include/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
endif()

# Compatibility: while the major version is 0 every minor version may break the API (semantic
# versioning), so a request for 0.1 accepts 0.1.x only (SameMinorVersion); from 1.0 on, any
# version of the same major (SameMajorVersion). Shared libraries (BUILD_SHARED_LIBS=ON) carry the
# same rule in their soname.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(DYOP_COMPATIBILITY SameMinorVersion)
  set(DYOP_SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
else()
  set(DYOP_COMPATIBILITY SameMajorVersion)
  set(DYOP_SOVERSION ${PROJECT_VERSION_MAJOR})
endif()
set_target_properties(${DYOP_PACKAGE_TARGETS} PROPERTIES VERSION ${PROJECT_VERSION}
                                                         SOVERSION ${DYOP_SOVERSION})

install(TARGETS ${DYOP_PACKAGE_TARGETS} EXPORT dyopTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
set(DYOP_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/dyop)
install(EXPORT dyopTargets NAMESPACE dyop:: DESTINATION ${DYOP_PACKAGE_DIR})

if(TARGET dyop_box2d_outlines)
  set(DYOP_WITH_OUTLINES TRUE)
else()
  set(DYOP_WITH_OUTLINES FALSE)
endif()
configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/dyopConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/dyopConfig.cmake
                              INSTALL_DESTINATION ${DYOP_PACKAGE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/dyopConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY ${DYOP_COMPATIBILITY})
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATAROOTDIR}/doc/dyop)
install(FILES ${PROJECT_BINARY_DIR}/dyopConfig.cmake ${PROJECT_BINARY_DIR}/dyopConfigVersion.cmake
        DESTINATION ${DYOP_PACKAGE_DIR})
