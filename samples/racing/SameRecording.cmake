# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DRACING=<crumple-racing-*> -DREPLAY=<crumple-replay> -DOUT=<dir> -P SameRecording.cmake
# Runs a racing session (the full 7 s the demo runs: a rail tumbling on the road from 4.2 s once blew up the
# recording, 4.7 s did not reach it) with dents on the game's thread and again with deferred dents on a 2-thread job
# system: the recordings and the deformed meshes (the cars, the brick wall and the fence the car breaks) must
# be byte-identical. Then the inline recording is replayed with no engine: the car and the props again.
# Then the props' FEM off the game's thread (--props-off-thread, landing a step later: another run), with the
# tasks inline and on 2 threads: byte-identical again, and replayed. Then the impulses on the dents' task too
# (--defer-impulses: the props hear of a hit a step later still, another run), inline and on 2 threads:
# byte-identical, and replayed.
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

run(${RACING} --no-pictures --out ${OUT}/inline)
run(${RACING} --no-pictures --out ${OUT}/deferred --threads 2 --defer-dents)
foreach(file race.crumple car.obj parked.obj fence.obj brick_wall.obj)
    expect_same(${OUT}/inline/${file} ${OUT}/deferred/${file} "${file} differs between inline and deferred dents")
endforeach()
run(${REPLAY} ${OUT}/inline/race.crumple --out ${OUT}/replayed)
foreach(pair "car.obj;object0.obj" "parked.obj;object1.obj" "fence.obj;prop0.obj" "brick_wall.obj;prop1.obj")
    list(GET pair 0 live)
    list(GET pair 1 replayed)
    expect_same(${OUT}/inline/${live} ${OUT}/replayed/${replayed} "the replayed ${replayed} differs from the live ${live}")
endforeach()

run(${RACING} --no-pictures --out ${OUT}/off_thread_inline --threads 1 --defer-dents --props-off-thread)
run(${RACING} --no-pictures --out ${OUT}/off_thread --threads 2 --defer-dents --props-off-thread)
foreach(file race.crumple car.obj parked.obj fence.obj brick_wall.obj)
    expect_same(${OUT}/off_thread_inline/${file} ${OUT}/off_thread/${file}
                "${file} differs between the props' FEM as an inline task and on 2 threads")
endforeach()
run(${REPLAY} ${OUT}/off_thread/race.crumple --out ${OUT}/off_thread_replayed)
foreach(pair "car.obj;object0.obj" "parked.obj;object1.obj" "fence.obj;prop0.obj" "brick_wall.obj;prop1.obj")
    list(GET pair 0 live)
    list(GET pair 1 replayed)
    expect_same(${OUT}/off_thread/${live} ${OUT}/off_thread_replayed/${replayed}
                "the replayed ${replayed} differs from the live ${live} (props off the thread)")
endforeach()

run(${RACING} --no-pictures --out ${OUT}/impulses_inline --threads 1 --defer-impulses --props-off-thread)
run(${RACING} --no-pictures --out ${OUT}/impulses --threads 2 --defer-impulses --props-off-thread)
foreach(file race.crumple car.obj parked.obj fence.obj brick_wall.obj)
    expect_same(${OUT}/impulses_inline/${file} ${OUT}/impulses/${file}
                "${file} differs between the impulses on an inline task and on 2 threads")
endforeach()
run(${REPLAY} ${OUT}/impulses/race.crumple --out ${OUT}/impulses_replayed)
foreach(pair "car.obj;object0.obj" "parked.obj;object1.obj" "fence.obj;prop0.obj" "brick_wall.obj;prop1.obj")
    list(GET pair 0 live)
    list(GET pair 1 replayed)
    expect_same(${OUT}/impulses/${live} ${OUT}/impulses_replayed/${replayed}
                "the replayed ${replayed} differs from the live ${live} (impulses on the task)")
endforeach()
