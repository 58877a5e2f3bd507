# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# The tetrahedral half of crumple::fem (paths relative to fem/).
set(CRUMPLE_FEM_TET_SOURCES
    src/BarycentricSearch.cpp
    src/ConjugateGradient.cpp
    src/DeformationGradient.cpp
    src/EdgeMatrix.cpp
    src/EElasticModel.cpp
    src/EFractureMode.cpp
    src/EImplicitPreconditioner.cpp
    src/EIntegrator.cpp
    src/FemMaterial.cpp
    src/FirstPiolaStress.cpp
    src/ModelStrain.cpp
    src/NodeBlockCholesky.cpp
    src/GreenStrain.cpp
    src/IsotropicMaterialMatrix.cpp
    src/LumpedNodeMass.cpp
    src/MaterialStress.cpp
    src/PolarRotation.cpp
    src/StableTimeStep.cpp
    src/StrainEnergyDensity.cpp
    src/TetElementPass.cpp
    src/TetContactMass.cpp
    src/TetElementRest.cpp
    src/TetFactoredPreconditioner.cpp
    src/TetFence.cpp
    src/TetGrid.cpp
    src/TetMesh.cpp
    src/TetNodalForces.cpp
    src/TetPassParallel.cpp
    src/TetPreconditioner.cpp
    src/TetRestSystemBlocks.cpp
    src/TetSolver.cpp
    src/TetSolverWorkspace.cpp
    src/TetStepper.cpp
    src/TetVolume.cpp)
