#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Installs what a fresh Debian machine lacks (as root; Slurm and munge for the sweep-on-a-cluster test),
# builds in Release, runs every default test.
# Long soak runs carry the CTest label "soak" and run in the bench job: scripts/bench.sh.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

crumple_ensure_packages slurmctld slurmd slurm-client munge
crumple_build -DCRUMPLE_BUILD_TESTS=ON -DCRUMPLE_BUILD_SAMPLES=ON -DCRUMPLE_BUILD_BENCH=ON
cd "$CRUMPLE_BUILD_DIR"
ctest --output-on-failure --parallel "$CRUMPLE_JOBS" --label-exclude soak
