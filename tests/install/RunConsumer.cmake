# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
file(REMOVE_RECURSE ${SCRATCH_DIR})
set(prefix ${SCRATCH_DIR}/prefix)
if(NOT BUILD_TYPE)
    set(BUILD_TYPE Release)
endif()

function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT result EQUAL 0)
        message(FATAL_ERROR "failed (${result}): ${ARGN}\n${output}")
    endif()
    message(STATUS "${output}")
endfunction()

run(${CMAKE_COMMAND} --install ${CRUMPLE_BINARY_DIR} --prefix ${prefix} --config ${BUILD_TYPE})
run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${SCRATCH_DIR}/build -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
    -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}
    "-DCMAKE_CXX_FLAGS=${CONSUMER_CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_LINKER_FLAGS}")
run(${CMAKE_COMMAND} --build ${SCRATCH_DIR}/build --config ${BUILD_TYPE})
run(${SCRATCH_DIR}/build/consumer)

# A Bullet-only game asks for the bullet component alone (when the package has it).
if(EXISTS ${prefix}/include/crumple/bullet/BulletAdapter.h)
    run(${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR}/../bullet_consumer -B ${SCRATCH_DIR}/bullet_build
        -DCMAKE_BUILD_TYPE=${BUILD_TYPE} -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}
        "-DCMAKE_CXX_FLAGS=${CONSUMER_CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_LINKER_FLAGS}")
    run(${CMAKE_COMMAND} --build ${SCRATCH_DIR}/bullet_build --config ${BUILD_TYPE})
    run(${SCRATCH_DIR}/bullet_build/bullet_consumer)
endif()

# The installed tools (when this build has them): they run from the prefix alone, on an installed
# scenario that needs no shared data (a box car), and the replay rebuilds its recording.
if(EXISTS ${CRUMPLE_BINARY_DIR}/tools/crash/crumple-crash AND EXISTS ${CRUMPLE_BINARY_DIR}/tools/replay/crumple-replay)
    foreach(tool crumple-crash crumple-replay)
        if(NOT EXISTS ${prefix}/bin/${tool})
            message(FATAL_ERROR "cmake --install did not install ${tool}")
        endif()
        run(${prefix}/bin/${tool} --version)
    endforeach()
    if(NOT EXISTS ${prefix}/share/doc/crumple/scenarios.md)
        message(FATAL_ERROR "cmake --install did not install the scenario schema (docs/scenarios.md)")
    endif()
    if(NOT EXISTS ${prefix}/share/doc/crumple/adapters.md)
        message(FATAL_ERROR "cmake --install did not install the engine contract (docs/adapters.md)")
    endif()
    run(${prefix}/bin/crumple-crash ${prefix}/share/crumple/scenarios/pole_frontal_32kmh.json --no-pictures
        --out ${SCRATCH_DIR}/pole)
    run(${prefix}/bin/crumple-replay ${SCRATCH_DIR}/pole/replay.crumple --out ${SCRATCH_DIR}/pole-replay --no-meshes)
endif()
