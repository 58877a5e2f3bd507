# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Live crash with a recording -> headless replay -> the two deformed meshes must be the same bytes.
# Then a corrupt copy must be refused (exit 2) with nothing written.
file(REMOVE_RECURSE ${DIR})
file(MAKE_DIRECTORY ${DIR})
function(run expected)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
    if(NOT result EQUAL expected)
        message(FATAL_ERROR "expected exit ${expected}, got ${result}: ${ARGN}\n${output}")
    endif()
    message(STATUS "${output}")
endfunction()
run(0 ${WALL_CRASH} --speed 14 --angle 20 --triangles 3000 --out ${DIR}/live --replay ${DIR}/crash.crumple)
run(0 ${REPLAY} ${DIR}/crash.crumple --out ${DIR}/replayed)
execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files ${DIR}/live/deformed.obj ${DIR}/replayed/object0.obj
    RESULT_VARIABLE different)
if(different)
    message(FATAL_ERROR "the replayed mesh differs from the live one")
endif()
# A truncated recording (cut in the middle), an empty one and a missing one are refused; nothing is written.
file(SIZE ${DIR}/crash.crumple size)
math(EXPR half "${size} / 2")
execute_process(COMMAND head -c ${half} ${DIR}/crash.crumple OUTPUT_FILE ${DIR}/truncated.crumple RESULT_VARIABLE cut)
if(cut)
    message(FATAL_ERROR "could not truncate the recording")
endif()
run(2 ${REPLAY} ${DIR}/truncated.crumple --out ${DIR}/refused)
file(WRITE ${DIR}/empty.crumple "")
run(2 ${REPLAY} ${DIR}/empty.crumple --out ${DIR}/refused)
run(2 ${REPLAY} ${DIR}/missing.crumple --out ${DIR}/refused)
if(EXISTS ${DIR}/refused)
    message(FATAL_ERROR "a refused replay wrote output")
endif()
