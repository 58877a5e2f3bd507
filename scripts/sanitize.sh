#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Builds everything with clang, AddressSanitizer and UndefinedBehaviorSanitizer (float-cast-overflow too, so
# a NaN or huge double cast to int is caught) in build-asan/ and runs the default tests under them; any
# sanitizer report fails the run. Third-party suppressions: fuzz/lsan.supp (assimp), each with its reason.
# Too long for CI's default job on 2 cores (a second full build): the bench job runs it (README, Tests).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

crumple_ensure_packages clang
build="$CRUMPLE_ROOT/build-asan"
sanitize="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=undefined,float-cast-overflow -fno-omit-frame-pointer"
CC=clang CXX=clang++ cmake -S "$CRUMPLE_ROOT" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS="$sanitize" -DCMAKE_EXE_LINKER_FLAGS="$sanitize" -DCMAKE_SHARED_LINKER_FLAGS="$sanitize" \
    -DCRUMPLE_BUILD_TESTS=ON -DCRUMPLE_BUILD_SAMPLES=ON -DCRUMPLE_BUILD_BENCH=OFF
cmake --build "$build" --parallel "$CRUMPLE_JOBS"
cd "$build"
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1"
export LSAN_OPTIONS="suppressions=$CRUMPLE_ROOT/fuzz/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --output-on-failure --parallel "$CRUMPLE_JOBS" --label-exclude "^(soak|fuzz)$"
