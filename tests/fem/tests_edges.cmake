# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Tests of the procedural edges and prop material presets of crumple::fem (paths relative to tests/).
set(CRUMPLE_FEM_EDGES_TESTS
    fem/CellCountForSectionsTest.cpp
    fem/EmbeddedMeshTest.cpp
    fem/ProceduralEdgeMeshTest.cpp
    fem/ProceduralEdgeSettingsTest.cpp
    fem/PropMaterialPresetTest.cpp
    fem/SplitMix64Test.cpp
    fem/TriangleNormalsTest.cpp
    fem/WallAxesTest.cpp)
