# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# The shipped mid-size preset checked against a line with b0 = 4.5 m/s instead of 2.173 must exit 1.
get_filename_component(root ${CMAKE_CURRENT_LIST_DIR}/../.. ABSOLUTE)
execute_process(COMMAND ${CRASH} ${root}/samples/calibration/mid_size_preset_check.json --campbell-check --b0 4.5
                        --b1 24.07 --out ${CMAKE_CURRENT_BINARY_DIR}/crash-wrong-line
                RESULT_VARIABLE code OUTPUT_VARIABLE out)
if(NOT code EQUAL 1)
    message(FATAL_ERROR "exited ${code}, expected 1:\n${out}")
endif()
