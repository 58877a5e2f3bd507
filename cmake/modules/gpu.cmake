# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::gpu — GLSL compute FEM in a headless EGL context. Needs EGL and OpenGL.
if(CRUMPLE_WITH_GPU)
    find_package(OpenGL QUIET COMPONENTS OpenGL EGL)
    if(NOT OpenGL_EGL_FOUND)
        message(STATUS "crumple: CRUMPLE_WITH_GPU switched OFF: EGL/OpenGL not found (apt-get install libegl-dev libgl-dev)")
        set(CRUMPLE_WITH_GPU OFF)
    elseif(NOT CRUMPLE_WITH_FEM OR NOT EXISTS ${PROJECT_SOURCE_DIR}/gpu/CMakeLists.txt)
        message(STATUS "crumple: CRUMPLE_WITH_GPU switched OFF: gpu/ needs fem/ and is not in this source tree yet")
        set(CRUMPLE_WITH_GPU OFF)
    else()
        add_subdirectory(${PROJECT_SOURCE_DIR}/gpu)
    endif()
endif()
