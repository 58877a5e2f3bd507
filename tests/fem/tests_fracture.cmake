# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Tests of plasticity, fracture and fragments (paths relative to tests/).
set(CRUMPLE_FEM_FRACTURE_TESTS
    fem/CrackSafeEnergyTest.cpp
    fem/FractureLinksTest.cpp
    fem/FractureTopologyTest.cpp
    fem/FractureInputChecksTest.cpp
    fem/PlasticFlowTest.cpp
    fem/TetCrackConvergenceTest.cpp
    fem/TetFractureTest.cpp
    fem/TetFragmentsTest.cpp
    fem/TetPlasticityTest.cpp)
