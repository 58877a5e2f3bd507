# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DCRASH=<crumple-crash> -DSCENARIO=<file> -DOUT=<dir> -P SweepFails.cmake
# A sweep of a scenario whose expectation fails at every speed exits 1, names the failing cases on its
# output, and writes each case's verdict (the expectation that failed) into sweep.csv.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${CRASH} ${SCENARIO} --sweep "speeds_km_h=10,15" --workers 2 --out ${OUT}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 1)
    message(FATAL_ERROR "the sweep exited ${code}, expected 1:\n${out}${err}")
endif()
if(NOT "${out}${err}" MATCHES "case 0 failed: residual_crush_m\\(roof\\)")
    message(FATAL_ERROR "the sweep does not name the failing case:\n${out}${err}")
endif()
file(STRINGS ${OUT}/sweep.csv rows REGEX ",failed: residual_crush_m\\(roof\\)")
list(LENGTH rows count)
if(NOT count EQUAL 2)
    message(FATAL_ERROR "${count} rows carry the failed expectation, expected 2")
endif()
