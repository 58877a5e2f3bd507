# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple_add_library(<name> SOURCES ... DEPENDS ...)
# Creates crumple_<name> with alias crumple::<name>, public headers in <dir>/include,
# private headers in <dir>/src, and our determinism flags.
function(crumple_add_library name)
    cmake_parse_arguments(ARG "" "" "SOURCES;DEPENDS" ${ARGN})
    add_library(crumple_${name} ${ARG_SOURCES})
    add_library(crumple::${name} ALIAS crumple_${name})
    set_target_properties(crumple_${name} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME crumple_${name})
    target_include_directories(crumple_${name}
        PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:include>
        PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
    target_link_libraries(crumple_${name} PUBLIC ${ARG_DEPENDS} PRIVATE $<BUILD_INTERFACE:crumple::compile_options>)
    if(BUILD_SHARED_LIBS)
        target_compile_definitions(crumple_${name} PRIVATE CRUMPLE_BUILDING_LIBRARY PUBLIC CRUMPLE_SHARED)
    endif()
    set_property(GLOBAL APPEND PROPERTY CRUMPLE_INSTALL_TARGETS crumple_${name})
    set_property(GLOBAL APPEND PROPERTY CRUMPLE_INSTALL_INCLUDE_DIRS ${CMAKE_CURRENT_SOURCE_DIR}/include)
endfunction()
