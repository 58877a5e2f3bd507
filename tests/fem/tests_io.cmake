# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Tests of the surface and frame export part of crumple::fem (paths relative to tests/).
set(CRUMPLE_FEM_IO_TESTS
    fem/FrameSequenceWriterTest.cpp
    fem/SurfaceFileTest.cpp
    fem/SurfaceMeshTest.cpp
    fem/SurfaceReadBack.cpp
    fem/TetBoundaryTest.cpp)
# crumple::fem_import (assimp + the tetgen program) has its own executable, test_fem_import.
if(TARGET crumple::fem_import)
    crumple_add_test(fem_import
        fem/import/ImportTestShapes.cpp
        fem/import/LoadSurfaceMeshTest.cpp
        fem/import/TetrahedralizeTest.cpp
        LINK crumple::fem_import)
endif()
