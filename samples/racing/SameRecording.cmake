# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# cmake -DRACING=<crumple-racing-*> -DREPLAY=<crumple-replay> -DOUT=<dir> -P SameRecording.cmake
# Runs a racing session (the full 7 s the demo runs: a rail tumbling on the road from 4.2 s once blew up the
# recording, 4.7 s did not reach it) with dents on the game's thread and again with deferred dents on a 2-thread job
# system: the recordings and the deformed meshes (the cars, the brick wall and the fence the car breaks) must
# be byte-identical. Then the inline recording is replayed with no engine: the car and the props again, on
# one thread, on two (the props beside the cars) and on three (their element passes on two of them).
# Then the props' FEM off the game's thread (--props-off-thread, landing a step later: another run), with the
# tasks inline and on 2 threads: byte-identical again, and replayed. Then the impulses on the dents' task too
# (--defer-impulses: the props hear of a hit a step later still, another run), inline and on 2 threads:
# byte-identical, and replayed.

# intent: every output made afresh (a file left by an earlier run would pass for one this run did not write)
if(NOT OUT)
    message(FATAL_ERROR "SameRecording.cmake needs -DOUT=<dir>")
endif()
file(REMOVE_RECURSE "${OUT}")

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

# The recording of the run in ${OUT}/${live_dir} replayed with no engine into ${OUT}/${out_dir}: the cars and
# the props byte for byte as the live run wrote them.
function(expect_replayed live_dir out_dir why)
    run(${REPLAY} ${OUT}/${live_dir}/race.crumple --out ${OUT}/${out_dir} ${ARGN})
    foreach(pair "car.obj;object0.obj" "parked.obj;object1.obj" "fence.obj;prop0.obj" "brick_wall.obj;prop1.obj")
        list(GET pair 0 live)
        list(GET pair 1 replayed)
        expect_same(${OUT}/${live_dir}/${live} ${OUT}/${out_dir}/${replayed}
                    "the replayed ${replayed} differs from the live ${live}${why}")
    endforeach()
endfunction()

run(${RACING} --no-pictures --out ${OUT}/inline)
run(${RACING} --no-pictures --out ${OUT}/deferred --threads 2 --defer-dents)
foreach(file race.crumple car.obj parked.obj fence.obj brick_wall.obj)
    expect_same(${OUT}/inline/${file} ${OUT}/deferred/${file} "${file} differs between inline and deferred dents")
endforeach()
expect_replayed(inline replayed "")
# With --threads 2 (the props replayed on a thread of their own beside the cars) and 3 (their element passes
# on two threads, though these props, 4,000 and 420 tetrahedra, are too small to split them: test_props
# replays a 4,500-tetrahedron panel that does) the same bytes again.
expect_replayed(inline replayed_2_threads " (replayed on 2 threads)" --threads 2)
expect_replayed(inline replayed_3_threads " (replayed on 3 threads)" --threads 3)

# A mode whose tasks run inline (--threads 1) and on 2 threads: the same bytes, and its recording replays.
function(same_on_two_threads name what)
    run(${RACING} --no-pictures --out ${OUT}/${name}_inline --threads 1 ${ARGN})
    run(${RACING} --no-pictures --out ${OUT}/${name} --threads 2 ${ARGN})
    foreach(file race.crumple car.obj parked.obj fence.obj brick_wall.obj)
        expect_same(${OUT}/${name}_inline/${file} ${OUT}/${name}/${file}
                    "${file} differs between ${what} as an inline task and on 2 threads")
    endforeach()
    expect_replayed(${name} ${name}_replayed " (${what} on a task)")
endfunction()
same_on_two_threads(off_thread "the props' FEM" --defer-dents --props-off-thread)
same_on_two_threads(impulses "the impulses" --defer-impulses --props-off-thread)
