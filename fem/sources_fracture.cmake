# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Plasticity, fracture, fragments and collision impulses of crumple::fem (paths relative to fem/).
set(CRUMPLE_FEM_FRACTURE_SOURCES
    src/CrackSafeEnergy.cpp
    src/FractureLinks.cpp
    src/FractureTopology.cpp
    src/GroupPrincipalStress.cpp
    src/OpenCracks.cpp
    src/PlasticFlow.cpp
    src/TetFragments.cpp)
