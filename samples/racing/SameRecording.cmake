# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DRACING=<crumple-racing-*> -DREPLAY=<crumple-replay> -DOUT=<dir> -P SameRecording.cmake
# Runs a racing session with dents on the game's thread and again with deferred dents on a 2-thread job
# system: the recordings and the deformed meshes (the cars and the fence the car breaks) must be
# byte-identical. Then the inline recording is replayed with no engine: the car and the fence again.
function(run)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_QUIET)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "${ARGN} exited ${code}")
    endif()
endfunction()
function(expect_same first second why)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${first} ${second} RESULT_VARIABLE different)
    if(different)
        message(FATAL_ERROR "${why}")
    endif()
endfunction()

run(${RACING} --duration 4.7 --no-pictures --out ${OUT}/inline)
run(${RACING} --duration 4.7 --no-pictures --out ${OUT}/deferred --threads 2 --defer-dents)
foreach(file race.crumple car.obj parked.obj fence.obj)
    expect_same(${OUT}/inline/${file} ${OUT}/deferred/${file} "${file} differs between inline and deferred dents")
endforeach()
run(${REPLAY} ${OUT}/inline/race.crumple --out ${OUT}/replayed)
foreach(pair "car.obj;object0.obj" "parked.obj;object1.obj" "fence.obj;prop0.obj")
    list(GET pair 0 live)
    list(GET pair 1 replayed)
    expect_same(${OUT}/inline/${live} ${OUT}/replayed/${replayed} "the replayed ${replayed} differs from the live ${live}")
endforeach()
