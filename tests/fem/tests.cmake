# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# test_fem: each part of crumple::fem lists its test files in its own include (tests_<part>.cmake).
set(CRUMPLE_FEM_TESTS "")
foreach(part IN ITEMS tet fracture edges io hex)
    string(TOUPPER ${part} upper)
    set(CRUMPLE_FEM_${upper}_TESTS "")
    include(${CMAKE_CURRENT_LIST_DIR}/tests_${part}.cmake OPTIONAL)
    list(APPEND CRUMPLE_FEM_TESTS ${CRUMPLE_FEM_${upper}_TESTS})
endforeach()
if(CRUMPLE_FEM_TESTS)
    crumple_add_test(fem ${CRUMPLE_FEM_TESTS} LINK crumple::fem crumple_scenes_fem)
    # The long cases are hidden from Catch2's discovered list ([.]) and tagged [soak]: one CTest entry runs
    # them, labelled soak, so scripts/test.sh leaves them out and the bench job (scripts/bench.sh) runs them.
    # (--warn NoTests: a filter that matches nothing fails instead of passing vacuously)
    add_test(NAME "fem: soak: the long hidden cases ([soak])" COMMAND test_fem "[soak]" --warn NoTests)
    set_tests_properties("fem: soak: the long hidden cases ([soak])" PROPERTIES LABELS soak SKIP_RETURN_CODE 77)
    # White-box tests of the solver's private kernels (STYLE rule 19: the test links the static target).
    target_include_directories(test_fem PRIVATE ${PROJECT_SOURCE_DIR}/fem/src)
    # White-box tests of private kernels (TetFactoredSolveTest, TetFactorRefreshTest): a shared build hides their symbols behind
    # the library's interface (CRUMPLE_API), so there the test compiles its own copy.
    if(BUILD_SHARED_LIBS)
        target_sources(test_fem PRIVATE ${PROJECT_SOURCE_DIR}/fem/src/NodeBlockCholesky.cpp
            ${PROJECT_SOURCE_DIR}/fem/src/TetElementPass.cpp ${PROJECT_SOURCE_DIR}/fem/src/TetPassParallel.cpp
            ${PROJECT_SOURCE_DIR}/fem/src/TetRestSystemBlocks.cpp ${PROJECT_SOURCE_DIR}/fem/src/TetFactoredPreconditioner.cpp)
    endif()
endif()
