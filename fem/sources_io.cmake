# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Surface import helpers and frame export of crumple::fem (paths relative to fem/). The tetgen import itself is
# the separate target crumple::fem_import (fem/import/), because it needs assimp.
set(CRUMPLE_FEM_IO_SOURCES
    src/ESurfaceFormat.cpp
    src/ExactNumber.cpp
    src/FrameSequenceWriter.cpp
    src/SurfaceFile.cpp
    src/SurfaceMesh.cpp
    src/SurfaceVolume.cpp
    src/TetBoundary.cpp)
