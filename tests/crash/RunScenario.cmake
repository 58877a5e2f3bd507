# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DCRASH=<crumple-crash> -DSCENARIO=<file> -DOUT=<dir> -DEXPECT_EXIT=<0|1|2> [-DEXPECT_TEXT=<regex>]
#       [-DREJECT_TEXT=<regex>] [-DARGS=<extra arguments, ;-separated>] [-DREPLAY=<crumple-replay>]
#       [-DNO_FOLDER=<a parent of OUT that a refused run must not leave behind>] -P RunScenario.cmake
# Runs one scenario and checks the exit status, the message, and what was (or was not) written; with REPLAY,
# also that replaying the run's recording headless gives a byte-identical deformed mesh (of a run that failed
# an expectation or a sanity check too: it still recorded what it did).
file(REMOVE_RECURSE ${OUT})
if(DEFINED NO_FOLDER)
    file(REMOVE_RECURSE ${NO_FOLDER})
endif()
execute_process(COMMAND ${CRASH} ${SCENARIO} --out ${OUT} ${ARGS} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "${out}${err}")
if(NOT code EQUAL EXPECT_EXIT)
    message(FATAL_ERROR "crumple-crash exited ${code}, expected ${EXPECT_EXIT}")
endif()
if(DEFINED EXPECT_TEXT AND NOT "${out}${err}" MATCHES "${EXPECT_TEXT}")
    message(FATAL_ERROR "the output does not say '${EXPECT_TEXT}'")
endif()
if(DEFINED REJECT_TEXT AND "${out}${err}" MATCHES "${REJECT_TEXT}")
    message(FATAL_ERROR "the output says '${REJECT_TEXT}'")
endif()
if(EXPECT_EXIT EQUAL 2)
    if(EXISTS ${OUT})
        message(FATAL_ERROR "a refused scenario wrote ${OUT}")
    endif()
    if(DEFINED NO_FOLDER AND EXISTS ${NO_FOLDER})
        message(FATAL_ERROR "a refused scenario left ${NO_FOLDER} behind")
    endif()
else()
    foreach(file report.json report.html deformed.obj timeseries.csv replay.crumple)
        if(NOT EXISTS ${OUT}/${file})
            message(FATAL_ERROR "${OUT}/${file} was not written")
        endif()
    endforeach()
endif()
if(DEFINED REPLAY AND EXPECT_EXIT LESS 2)
    execute_process(COMMAND ${REPLAY} ${OUT}/replay.crumple --out ${OUT}/replay RESULT_VARIABLE code OUTPUT_QUIET)
    if(NOT code EQUAL 0)
        message(FATAL_ERROR "crumple-replay exited ${code}")
    endif()
    execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${OUT}/deformed.obj ${OUT}/replay/object0.obj
        RESULT_VARIABLE different)
    if(different)
        message(FATAL_ERROR "the replayed mesh differs from the live one")
    endif()
endif()
