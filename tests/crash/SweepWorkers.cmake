# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DCRASH=<crumple-crash> -DSCENARIO=<file> -DOUT=<dir> -P SweepWorkers.cmake
# The same sweep in 1 and in 3 worker processes writes the same sweep.csv, with one ok row per case, and a plot.
set(sweep "speeds_km_h=20,35,50;angles_deg=0,20;offsets_m=0,0.4")
foreach(workers 1 3)
    file(REMOVE_RECURSE ${OUT}/w${workers})
    execute_process(COMMAND ${CRASH} ${SCENARIO} --sweep "${sweep}" --workers ${workers} --out ${OUT}/w${workers}
                    RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "the sweep in ${workers} workers exited ${code}:\n${out}${err}")
    endif()
    if(NOT EXISTS ${OUT}/w${workers}/sweep.png)
        message(FATAL_ERROR "no sweep.png")
    endif()
endforeach()
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/w1/sweep.csv ${OUT}/w3/sweep.csv RESULT_VARIABLE different)
if(different)
    message(FATAL_ERROR "sweep.csv depends on the number of workers")
endif()
file(STRINGS ${OUT}/w1/sweep.csv rows REGEX ",ok$")
list(LENGTH rows count)
if(NOT count EQUAL 12)
    message(FATAL_ERROR "${count} ok rows, expected 12")
endif()
