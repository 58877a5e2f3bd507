#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# The bench job: builds crumple-bench, prints its table, writes bench-output/results.csv, runs the long
# soak tests (CTest label "soak"), then the fuzz targets for FUZZ_SECONDS each (scripts/fuzz.sh, default 600)
# and the whole test suite under ASan + UBSan (scripts/sanitize.sh): both need a clang build of their own,
# too long for CI's default job on 2 cores.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

crumple_ensure_packages
crumple_build -DCRUMPLE_BUILD_TESTS=ON -DCRUMPLE_BUILD_BENCH=ON
mkdir -p "$CRUMPLE_ROOT/bench-output"
"$CRUMPLE_BUILD_DIR/bench/crumple-bench" --csv "$CRUMPLE_ROOT/bench-output/results.csv" "$@"
cd "$CRUMPLE_BUILD_DIR"
ctest --output-on-failure --label-regex soak --no-tests=error
FUZZ_SECONDS="${FUZZ_SECONDS:-600}" "$CRUMPLE_ROOT/scripts/fuzz.sh"
"$CRUMPLE_ROOT/scripts/sanitize.sh"
