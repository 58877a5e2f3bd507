# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Procedural broken edges (display mesh embedded in the tets) and prop material presets (paths relative to fem/).
set(CRUMPLE_FEM_EDGES_SOURCES
    src/EmbeddedMesh.cpp
    src/ProceduralEdgeSettings.cpp
    src/TriangleNormals.cpp)
