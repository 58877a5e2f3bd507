# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# test_gpu: the compute module and the GPU FEM solver (on llvmpipe where no GPU exists).
crumple_add_test(gpu
    gpu/ComputeDeviceTest.cpp
    gpu/GpuCoarseSpaceTest.cpp
    gpu/FloatTetReference.cpp
    gpu/GpuFractureTest.cpp
    gpu/GpuImplicitStepTest.cpp
    gpu/GpuPlasticityTest.cpp
    gpu/GpuTestScenes.cpp
    gpu/GpuTetSolverTest.cpp
    LINK crumple::gpu crumple_scenes_fem)
