# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# test_fem: the tet and hex halves each list their test files in their own include.
set(CRUMPLE_FEM_TET_TESTS "")
set(CRUMPLE_FEM_HEX_TESTS "")
include(${CMAKE_CURRENT_LIST_DIR}/tests_tet.cmake OPTIONAL)
include(${CMAKE_CURRENT_LIST_DIR}/tests_hex.cmake OPTIONAL)
if(CRUMPLE_FEM_TET_TESTS OR CRUMPLE_FEM_HEX_TESTS)
    crumple_add_test(fem ${CRUMPLE_FEM_TET_TESTS} ${CRUMPLE_FEM_HEX_TESTS} LINK crumple::fem)
endif()
