# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DRACING=<crumple-racing-*> -DOUT=<dir> -P SameRecording.cmake
# Runs a racing session with dents on the game's thread and again with deferred dents on a 2-thread job
# system: the recordings and the deformed meshes must be byte-identical.
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
foreach(file race.crumple car.obj parked.obj)
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/inline/${file} ${OUT}/deferred/${file}
        RESULT_VARIABLE different)
    if(different)
        message(FATAL_ERROR "${file} differs between inline and deferred dents")
    endif()
endforeach()
