# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Tests of the surface and frame export part of crumple::fem (paths relative to tests/).
set(CRUMPLE_FEM_IO_TESTS
    fem/FrameSequenceWriterTest.cpp
    fem/SurfaceFileTest.cpp
    fem/SurfaceMeshTest.cpp
    fem/SurfaceReadBack.cpp
    fem/TetBoundaryTest.cpp)
