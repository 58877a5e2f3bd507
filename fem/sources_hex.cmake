# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::fem, hexahedral half: structured hex meshes, trilinear / incompatible-mode element stiffness,
# factorized static solve and precomputed compliance (instant quasi-static dents), saved and loaded.
set(CRUMPLE_FEM_HEX_SOURCES
    src/HexComplianceCsv.cpp
    src/HexComplianceFile.cpp
    src/HexCompliancePrecompute.cpp
    src/HexComplianceSolve.cpp
    src/HexElementStiffness.cpp
    src/HexMaterial.cpp
    src/HexMesh.cpp
    src/HexNodesInBox.cpp
    src/HexSourceCrc.cpp
    src/HexStaticPrecompute.cpp
    src/HexStaticSolve.cpp
    src/HexStiffness.cpp)
