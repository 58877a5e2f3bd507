# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# test_fem, hexahedral half (paths relative to tests/).
set(CRUMPLE_FEM_HEX_TESTS
    fem/HexComplianceCsvTest.cpp
    fem/HexComplianceFileTest.cpp
    fem/HexComplianceTest.cpp
    fem/HexElementStiffnessTest.cpp
    fem/HexMaterialTest.cpp
    fem/HexMeshTest.cpp
    fem/HexStaticSolveTest.cpp
    fem/HexStiffnessTest.cpp)
