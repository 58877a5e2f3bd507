# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# crumple::props — props in the damage flow (collision impulses onto FEM nodes, FemProp). Needs fem; uses gpu
# when it was built (include this after modules/gpu).
if(CRUMPLE_WITH_FEM)
    add_subdirectory(${PROJECT_SOURCE_DIR}/props ${PROJECT_BINARY_DIR}/props)
endif()
