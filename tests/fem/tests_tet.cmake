# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Tests of the tetrahedral half of crumple::fem (paths relative to tests/).
set(CRUMPLE_FEM_TET_TESTS
    fem/AllocationCounter.cpp
    fem/ConjugateGradientTest.cpp
    fem/FactorRefreshLedgerTest.cpp
    fem/FemInputBoundsTest.cpp
    fem/FemMaterialTest.cpp
    fem/PolarRotationTest.cpp
    fem/TetAnchoredElementsTest.cpp
    fem/StableTimeStepTest.cpp
    fem/TetCantileverTest.cpp
    fem/TetCoarseSpaceTest.cpp
    fem/TetContactMassTest.cpp
    fem/TetFactoredSolveTest.cpp
    fem/TetFactorRefreshTest.cpp
    fem/TetEnergyTest.cpp
    fem/TetFenceTest.cpp
    fem/TetGridTest.cpp
    fem/TetGroundTest.cpp
    fem/TetMeshTest.cpp
    fem/TetNodalForcesTest.cpp
    fem/TetPassStressTest.cpp
    fem/TetReferenceEnergyTest.cpp
    fem/TetPatchTest.cpp
    fem/TetSleepTest.cpp
    fem/TetSolverTest.cpp
    fem/TetStepperTest.cpp
    fem/TetStressTest.cpp)
