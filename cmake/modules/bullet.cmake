# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::bullet — the Bullet adapter. Needs Debian's libbullet-dev (found through pkg-config).
if(CRUMPLE_WITH_BULLET)
    find_package(PkgConfig QUIET)
    if(PkgConfig_FOUND)
        pkg_check_modules(BULLET QUIET IMPORTED_TARGET bullet)
    endif()
    if(NOT BULLET_FOUND)
        message(STATUS "crumple: CRUMPLE_WITH_BULLET switched OFF: Bullet not found (apt-get install libbullet-dev pkg-config)")
        set(CRUMPLE_WITH_BULLET OFF)
    else()
        add_subdirectory(${PROJECT_SOURCE_DIR}/plugin/bullet)
    endif()
endif()
