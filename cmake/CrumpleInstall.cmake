# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake --install: headers, libraries and a CMake package, so a game does
#   find_package(crumple CONFIG REQUIRED)  and links crumple::core.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

get_property(crumple_targets GLOBAL PROPERTY CRUMPLE_INSTALL_TARGETS)
get_property(crumple_include_dirs GLOBAL PROPERTY CRUMPLE_INSTALL_INCLUDE_DIRS)

install(TARGETS ${crumple_targets} crumple_compile_options EXPORT crumpleTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
foreach(dir IN LISTS crumple_include_dirs)
    install(DIRECTORY ${dir}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endforeach()
# The contract for joining an engine that has no adapter (docs/adapters.md), beside the headers it explains.
install(FILES ${PROJECT_SOURCE_DIR}/docs/adapters.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(EXPORT crumpleTargets NAMESPACE crumple:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/crumple)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/crumpleConfig.cmake.in
    ${PROJECT_BINARY_DIR}/crumpleConfig.cmake
    INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/crumple)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/crumpleConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/crumpleConfig.cmake ${PROJECT_BINARY_DIR}/crumpleConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/crumple)
