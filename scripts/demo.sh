#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# The main job: a scripted racing session in Bullet (and the same in ODE). A car with a deformable body
# knocks bricks out of a garden wall, scrapes along barriers, breaks through a wooden fence whose pieces fly, and hits a parked car; each run writes a replay file, the deformed meshes (OBJ)
# and PNG pictures (before/after and a frame sequence, rendered headless on EGL). The Bullet recording is
# then replayed with no engine at all, and its mesh compared with the live one.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

crumple_ensure_packages
crumple_build -DCRUMPLE_BUILD_TESTS=OFF -DCRUMPLE_BUILD_SAMPLES=ON
out="${1:-$CRUMPLE_ROOT/demo-output}"
bin="$CRUMPLE_BUILD_DIR/samples"
crash="$CRUMPLE_BUILD_DIR/tools/crash/crumple-crash"
replay="$CRUMPLE_BUILD_DIR/tools/replay/crumple-replay"
mkdir -p "$out"

# A replayed mesh must be the live one byte for byte: same_mesh LIVE REPLAYED WHAT...
same_mesh() {
    local live="$1" replayed="$2"
    shift 2
    if cmp -s "$live" "$replayed"; then
        echo "replayed $* mesh is byte-identical to the live one"
    else
        echo "replayed $* mesh differs from the live one" >&2
        exit 1
    fi
}
if [ ! -x "$bin/crumple-racing-bullet" ] || [ ! -x "$crash" ]; then
    echo "crumple demo: the racing samples were not built (see the configure messages above)" >&2
    exit 1
fi

echo "== Crash test: the shipped Toy Car, full frontal into a rigid barrier at 56 km/h"
"$crash" "$CRUMPLE_ROOT/samples/scenarios/frontal_rigid_barrier_56kmh.json" --out "$out/crash-frontal-56"
"$replay" "$out/crash-frontal-56/replay.crumple" --out "$out/crash-frontal-56/replay" > /dev/null
same_mesh "$out/crash-frontal-56/deformed.obj" "$out/crash-frontal-56/replay/object0.obj" crash

echo; echo "== Bullet racing session"
"$bin/crumple-racing-bullet" --out "$out/racing-bullet"
if [ -x "$bin/crumple-racing-ode" ]; then
    echo; echo "== ODE racing session"
    "$bin/crumple-racing-ode" --out "$out/racing-ode"
fi
echo; echo "== The Bullet session as a game runs it: its job system on 2 threads, dents deferred a frame,"
echo "   the props' FEM off the game's thread (a different run: each lands a step later)"
"$bin/crumple-racing-bullet" --threads 2 --defer-dents --props-off-thread --no-pictures --out "$out/racing-bullet-jobs" |
    grep -E "^(fence:|brick wall:|props' FEM:|physics frames|wrote)"
# replayed on 2 threads too: the props beside the cars
"$replay" "$out/racing-bullet-jobs/race.crumple" --out "$out/racing-bullet-jobs/replay" --threads 2 > /dev/null
same_mesh "$out/racing-bullet-jobs/car.obj" "$out/racing-bullet-jobs/replay/object0.obj" "threaded session's car"
same_mesh "$out/racing-bullet-jobs/fence.obj" "$out/racing-bullet-jobs/replay/prop0.obj" "threaded session's fence"
same_mesh "$out/racing-bullet-jobs/brick_wall.obj" "$out/racing-bullet-jobs/replay/prop1.obj" "threaded session's brick wall"

echo; echo "== Headless replay of the Bullet recording (no physics engine)"
"$replay" "$out/racing-bullet/race.crumple" --out "$out/replay"
same_mesh "$out/racing-bullet/car.obj" "$out/replay/object0.obj" car
same_mesh "$out/racing-bullet/fence.obj" "$out/replay/prop0.obj" "fence (cracks and pieces)"
same_mesh "$out/racing-bullet/brick_wall.obj" "$out/replay/prop1.obj" "brick wall (bricks knocked out)"

echo
echo "crumple demo: crash report: $out/crash-frontal-56/report.html (report.json, pictures, deformed.obj, replay.crumple beside it)"
echo "crumple demo: pictures are in $out/racing-bullet (before.png, after.png, frames/) and $out/racing-ode;"
echo "              deformed meshes (OBJ) and replay files (race.crumple) beside them."
