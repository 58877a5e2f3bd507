#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Builds the fuzz targets with clang, libFuzzer, AddressSanitizer and UndefinedBehaviorSanitizer (NaN-to-int
# casts included) in build-fuzz/, writes their seed corpora, and runs each target for FUZZ_SECONDS (default
# 60) on them. Prints each target's executions and exits 1 on the first crash, leak or sanitizer report (the
# input is kept as build-fuzz/fuzz/crash-<target>-*: add it to fuzz/regressions/<target>/). The bench job
# runs it; docs/fuzzing.md says how long and what was found.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

crumple_ensure_packages clang
FUZZ_SECONDS="${FUZZ_SECONDS:-60}"
build="$CRUMPLE_ROOT/build-fuzz"
sanitize="-fsanitize=address,undefined,float-cast-overflow -fno-sanitize-recover=undefined,float-cast-overflow"
CC=clang CXX=clang++ cmake -S "$CRUMPLE_ROOT" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS="$sanitize -fsanitize=fuzzer-no-link -DFUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION" \
    -DCMAKE_EXE_LINKER_FLAGS="$sanitize" -DCRUMPLE_FUZZ=ON -DCRUMPLE_FUZZ_SECONDS="$FUZZ_SECONDS" \
    -DCRUMPLE_BUILD_TESTS=OFF -DCRUMPLE_BUILD_SAMPLES=OFF -DCRUMPLE_BUILD_BENCH=OFF -DCRUMPLE_WITH_GPU=OFF \
    -DCRUMPLE_WITH_BULLET=OFF -DCRUMPLE_WITH_ODE=OFF
targets=$(cmake --build "$build" --target help | sed -n 's/^\.\.\. \(crumple-fuzz-[a-z_-]*\).*/\1/p')
# shellcheck disable=SC2086
cmake --build "$build" --parallel "$CRUMPLE_JOBS" --target $targets
cd "$build"
# assimp leaks on some malformed files (third-party code, not Crumple's): docs/fuzzing.md lists them.
export LSAN_OPTIONS="suppressions=$CRUMPLE_ROOT/fuzz/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1"
ctest --output-on-failure -L "fuzz-corpus"
ctest --output-on-failure -V --parallel "$CRUMPLE_JOBS" -L "^fuzz$" 2>&1 | tee fuzz.log | grep -E "Done [0-9]+ runs|Test #|ERROR|SUMMARY" || true
grep -q "tests passed, 0 tests failed" fuzz.log || { echo "crumple: a fuzz target failed: see $build/fuzz.log" >&2; exit 1; }
echo "crumple: every fuzz target ran ${FUZZ_SECONDS} s without a finding"
