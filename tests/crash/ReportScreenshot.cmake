# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DCRASH=... -DCHROMIUM=... -DCHECK=... -DSCENARIO=... -DOUT=... -P ReportScreenshot.cmake
# Runs a scenario with pictures, opens its report.html in headless Chromium and checks the screenshot shows
# the pictures (crumple-png-check; the window is tall enough for the tables above them). Without an EGL context the run has no pictures: the test says so and passes
# only if the report says why.
file(REMOVE_RECURSE ${OUT})
execute_process(COMMAND ${CRASH} ${SCENARIO} --out ${OUT} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
    message(FATAL_ERROR "crumple-crash exited ${code}:\n${out}${err}")
endif()
if(NOT EXISTS ${OUT}/after_front.png)
    if("${out}" MATCHES "pictures skipped")
        message(STATUS "no EGL here, no pictures to show: ${out}")
        return()
    endif()
    message(FATAL_ERROR "no pictures and no reason given")
endif()
foreach(plot deceleration velocity energy)
    if(NOT EXISTS ${OUT}/${plot}.png)
        message(FATAL_ERROR "no time-history plot ${plot}.png beside the pictures")
    endif()
endforeach()
file(READ ${OUT}/report.html html)
if(NOT html MATCHES "<h2>Time histories</h2>")
    message(FATAL_ERROR "report.html has no time histories")
endif()
execute_process(COMMAND ${CHROMIUM} --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1200,3200
                        --screenshot=${OUT}/screenshot.png file://${OUT}/report.html
                RESULT_VARIABLE code OUTPUT_QUIET ERROR_QUIET TIMEOUT 120)
if(NOT code EQUAL 0 OR NOT EXISTS ${OUT}/screenshot.png)
    message(FATAL_ERROR "chromium exited ${code} without a screenshot")
endif()
execute_process(COMMAND ${CHECK} ${OUT}/screenshot.png RESULT_VARIABLE code OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT code EQUAL 0)
    message(FATAL_ERROR "the report's screenshot is blank or shows no picture")
endif()
