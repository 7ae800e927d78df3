# `cmake --install BUILD [--prefix DIR]`: the layers' static libraries, their headers, the
# `catena` command and its plot scripts (apps/CMakeLists.txt), and the CMake package
# Catena, with which another project uses the libraries:
#   find_package(Catena REQUIRED)
#   target_link_libraries(app PRIVATE Catena::post)   # a layer and those below it
#   target_link_libraries(app PRIVATE Catena::catena) # every layer
include(CMakePackageConfigHelpers)

set(CATENA_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/Catena
    CACHE STRING "Where the CMake package Catena is installed (relative to the prefix)")

get_property(catena_layers GLOBAL PROPERTY CATENA_LAYERS)
install(TARGETS ${catena_layers} catena_libraries EXPORT CatenaTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/include/catena DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        FILES_MATCHING PATTERN "*.hpp")
install(EXPORT CatenaTargets NAMESPACE Catena:: DESTINATION ${CATENA_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/CatenaConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/CatenaConfig.cmake
                              INSTALL_DESTINATION ${CATENA_INSTALL_CMAKEDIR})
# Which installed versions satisfy find_package(Catena X.Y): the C++ interface of the
# libraries makes no promise across versions that change it. Semantic versioning: before
# 1.0 a minor release may change it (0.2 does not satisfy a request for 0.1), from 1.0 on
# only a major release does (SameMajorVersion). Not AnyNewerVersion: a project written
# against 1.x would accept a 2.0 whose headers it no longer compiles with.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(catena_compatibility SameMinorVersion)
else()
  set(catena_compatibility SameMajorVersion)
endif()
write_basic_package_version_file(${CMAKE_BINARY_DIR}/CatenaConfigVersion.cmake
                                 COMPATIBILITY ${catena_compatibility})
install(FILES ${CMAKE_BINARY_DIR}/CatenaConfig.cmake ${CMAKE_BINARY_DIR}/CatenaConfigVersion.cmake
              ${CMAKE_SOURCE_DIR}/cmake/FindMETIS.cmake
        DESTINATION ${CATENA_INSTALL_CMAKEDIR})
