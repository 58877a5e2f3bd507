# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Procedural broken edges (display mesh embedded in the tets) and prop material presets (paths relative to fem/).
set(CRUMPLE_FEM_EDGES_SOURCES
    src/CellCountForSections.cpp
    src/EmbeddedMesh.cpp
    src/EPropMaterial.cpp
    src/ProceduralEdgeMesh.cpp
    src/ProceduralEdgeSettings.cpp
    src/PropMaterialPreset.cpp
    src/TriangleNormals.cpp
    src/WallAxes.cpp)
