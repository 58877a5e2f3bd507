# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::bullet — the Bullet adapter. Needs Debian's libbullet-dev.
if(CRUMPLE_WITH_BULLET)
    find_package(Bullet QUIET)
    if(NOT BULLET_FOUND)
        message(STATUS "crumple: CRUMPLE_WITH_BULLET switched OFF: Bullet not found (apt-get install libbullet-dev)")
        set(CRUMPLE_WITH_BULLET OFF)
    elseif(NOT EXISTS ${PROJECT_SOURCE_DIR}/plugin/bullet/CMakeLists.txt)
        message(STATUS "crumple: CRUMPLE_WITH_BULLET switched OFF: plugin/bullet is not in this source tree yet")
        set(CRUMPLE_WITH_BULLET OFF)
    else()
        add_subdirectory(${PROJECT_SOURCE_DIR}/plugin/bullet)
    endif()
endif()
