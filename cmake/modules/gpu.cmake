# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::gpu — the FEM solver as GLSL compute shaders in a headless EGL context (crumple::egl). Needs fem,
# EGL and the OpenGL core headers (apt-get install libegl-dev libgl-dev); at run time a driver (Mesa's
# llvmpipe where no GPU exists: libegl-mesa0 libgl1-mesa-dri).
if(CRUMPLE_WITH_GPU)
    find_package(OpenGL QUIET COMPONENTS OpenGL EGL)
    find_path(CRUMPLE_GLCOREARB_INCLUDE_DIR GL/glcorearb.h HINTS ${OPENGL_INCLUDE_DIR}
        DOC "Directory holding GL/glcorearb.h")
    if(NOT OpenGL_EGL_FOUND OR NOT CRUMPLE_GLCOREARB_INCLUDE_DIR)
        message(STATUS "crumple: CRUMPLE_WITH_GPU switched OFF: EGL/OpenGL not found (apt-get install libegl-dev libgl-dev)")
        set(CRUMPLE_WITH_GPU OFF)
    elseif(NOT CRUMPLE_WITH_FEM)
        message(STATUS "crumple: CRUMPLE_WITH_GPU switched OFF: it needs CRUMPLE_WITH_FEM")
        set(CRUMPLE_WITH_GPU OFF)
    else()
        if(NOT TARGET crumple_egl)
            add_subdirectory(${PROJECT_SOURCE_DIR}/gpu/egl ${PROJECT_BINARY_DIR}/gpu/egl)
        endif()
        add_subdirectory(${PROJECT_SOURCE_DIR}/gpu/compute ${PROJECT_BINARY_DIR}/gpu/compute)
    endif()
endif()
