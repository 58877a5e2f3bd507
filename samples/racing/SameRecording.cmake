# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DRACING=<crumple-racing-*> -DREPLAY=<crumple-replay> -DOUT=<dir> -P SameRecording.cmake
# Runs a racing session with dents on the game's thread and again with deferred dents on a 2-thread job
# system: the recordings and the deformed meshes (the cars and the fence the car breaks) must be
# byte-identical. Then the inline recording is replayed with no engine: the car and the fence again.
foreach(mode inline deferred)
    set(args --duration 4.7 --no-pictures --out ${OUT}/${mode})
    if(mode STREQUAL "deferred")
        list(APPEND args --threads 2 --defer-dents)
    endif()
    execute_process(COMMAND ${RACING} ${args} RESULT_VARIABLE code OUTPUT_QUIET)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "${RACING} ${args} exited ${code}")
    endif()
endforeach()
foreach(file race.crumple car.obj parked.obj fence.obj)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/inline/${file} ${OUT}/deferred/${file}
        RESULT_VARIABLE different)
    if(different)
        message(FATAL_ERROR "${file} differs between inline and deferred dents")
    endif()
endforeach()
execute_process(COMMAND ${REPLAY} ${OUT}/inline/race.crumple --out ${OUT}/replayed RESULT_VARIABLE code OUTPUT_QUIET)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "${REPLAY} ${OUT}/inline/race.crumple exited ${code}")
endif()
foreach(pair "car.obj;object0.obj" "parked.obj;object1.obj" "fence.obj;prop0.obj")
    list(GET pair 0 live)
    list(GET pair 1 replayed)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/inline/${live} ${OUT}/replayed/${replayed}
        RESULT_VARIABLE different)
    if(different)
        message(FATAL_ERROR "the replayed ${replayed} differs from the live ${live}")
    endif()
endforeach()
