# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::fem — destructible props (tetrahedral FEM). Needs only Eigen.
if(CRUMPLE_WITH_FEM)
    if(EXISTS ${PROJECT_SOURCE_DIR}/fem/CMakeLists.txt)
        add_subdirectory(${PROJECT_SOURCE_DIR}/fem)
    else()
        message(STATUS "crumple: CRUMPLE_WITH_FEM switched OFF: fem/ is not in this source tree yet")
        set(CRUMPLE_WITH_FEM OFF)
    endif()
endif()
