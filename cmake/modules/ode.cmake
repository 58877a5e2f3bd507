# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::ode — the ODE adapter. Needs Debian's libode-dev (found through pkg-config).
if(CRUMPLE_WITH_ODE)
    find_package(PkgConfig QUIET)
    if(PkgConfig_FOUND)
        pkg_check_modules(ODE QUIET IMPORTED_TARGET ode)
    endif()
    if(NOT ODE_FOUND)
        message(STATUS "crumple: CRUMPLE_WITH_ODE switched OFF: ODE not found (apt-get install libode-dev pkg-config)")
        set(CRUMPLE_WITH_ODE OFF)
    else()
        add_subdirectory(${PROJECT_SOURCE_DIR}/plugin/ode)
    endif()
endif()
