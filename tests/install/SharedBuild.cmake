# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DSOURCE_DIR=<checkout> -DSCRATCH_DIR=<dir> -DCXX_COMPILER=<c++> -DCONSUMER_SOURCE_DIR=<tests/install/consumer>
#       -P SharedBuild.cmake
# Builds the libraries with BUILD_SHARED_LIBS=ON (hidden visibility, CRUMPLE_API exports), checks that the
# shared objects export the public API and hide the private one, then installs them and builds and runs the
# find_package consumers (RunConsumer.cmake). The build folder is kept: a rerun builds only what changed.
set(build ${SCRATCH_DIR}/build)

function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "failed (${result}): ${ARGN}\n${output}")
    endif()
endfunction()

run(${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${build} -DCMAKE_BUILD_TYPE=Release -DBUILD_SHARED_LIBS=ON
    -DCRUMPLE_BUILD_TESTS=OFF -DCRUMPLE_BUILD_SAMPLES=OFF -DCRUMPLE_BUILD_BENCH=OFF -DCRUMPLE_BUILD_TOOLS=OFF
    -DCMAKE_CXX_COMPILER=${CXX_COMPILER})
run(${CMAKE_COMMAND} --build ${build} --parallel 2)

# The public API is exported and the private one is not: a class of a public header, a function of one, and a
# class of a private header (ffd/src), read from the dynamic symbol table.
find_program(NM nm REQUIRED)
execute_process(COMMAND ${NM} -DC --defined-only ${build}/ffd/libcrumple_ffd.so OUTPUT_VARIABLE symbols RESULT_VARIABLE result)
if(NOT result EQUAL 0)
    message(FATAL_ERROR "nm could not read ${build}/ffd/libcrumple_ffd.so")
endif()
foreach(public "crumple::ffd::FfdDeformer::Create" "crumple::ffd::RefineLongEdges" "crumple::ffd::ValidateTriangleMesh")
    string(FIND "${symbols}" "${public}" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "libcrumple_ffd.so does not export ${public} (a public header's declaration without CRUMPLE_API?)")
    endif()
endforeach()
string(FIND "${symbols}" "crumple::ffd::CellSurfaceIndex::" at)
if(NOT at EQUAL -1)
    message(FATAL_ERROR "libcrumple_ffd.so exports the private CellSurfaceIndex: the visibility preset is not hidden")
endif()
message(STATUS "libcrumple_ffd.so exports the public API and hides the private one")

execute_process(COMMAND ${CMAKE_COMMAND} -DCRUMPLE_BINARY_DIR=${build} -DCONSUMER_SOURCE_DIR=${CONSUMER_SOURCE_DIR}
                        -DSCRATCH_DIR=${SCRATCH_DIR}/consumer -DBUILD_TYPE=Release -DCONSUMER_CXX_COMPILER=${CXX_COMPILER}
                        -P ${CMAKE_CURRENT_LIST_DIR}/RunConsumer.cmake
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
message(STATUS "${output}")
if(NOT result EQUAL 0)
    message(FATAL_ERROR "the consumers of the shared install failed")
endif()
