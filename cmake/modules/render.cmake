# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::egl (headless OpenGL context through EGL) and crumple::render (PNG pictures of meshes).
# Needs EGL, the OpenGL core headers and stb: apt-get install libegl-dev libgl-dev libstb-dev; at run time
# a driver (libegl-mesa0 libgl1-mesa-dri give Mesa's llvmpipe on machines without a GPU).
option(CRUMPLE_WITH_RENDER "Build the headless mesh renderer (crumple::egl, crumple::render)" ON)
if(CRUMPLE_WITH_RENDER)
    find_package(OpenGL QUIET COMPONENTS OpenGL EGL)
    find_path(CRUMPLE_GLCOREARB_INCLUDE_DIR GL/glcorearb.h HINTS ${OPENGL_INCLUDE_DIR}
        DOC "Directory holding GL/glcorearb.h")
    find_path(CRUMPLE_STB_INCLUDE_DIR stb/stb_image_write.h DOC "Directory holding stb/stb_image_write.h")
    if(NOT OpenGL_EGL_FOUND OR NOT OpenGL_OpenGL_FOUND OR NOT CRUMPLE_GLCOREARB_INCLUDE_DIR)
        message(STATUS "crumple: CRUMPLE_WITH_RENDER switched OFF: EGL/OpenGL not found (apt-get install libegl-dev libgl-dev)")
        set(CRUMPLE_WITH_RENDER OFF)
    elseif(NOT EXISTS "${CRUMPLE_STB_INCLUDE_DIR}/stb/stb_image_write.h")
        message(STATUS "crumple: CRUMPLE_WITH_RENDER switched OFF: stb/stb_image_write.h not found (apt-get install libstb-dev)")
        set(CRUMPLE_WITH_RENDER OFF)
    else()
        # gpu/egl may already be added by another module that needs a context (the GPU FEM backend).
        if(NOT TARGET crumple_egl)
            add_subdirectory(${PROJECT_SOURCE_DIR}/gpu/egl ${PROJECT_BINARY_DIR}/gpu/egl)
        endif()
        add_subdirectory(${PROJECT_SOURCE_DIR}/render ${PROJECT_BINARY_DIR}/render)
    endif()
endif()
