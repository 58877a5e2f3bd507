#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# The main job, until the engine adapters land: a box-shaped car driven into a wall head-on and at 30
# degrees through the core API (scripted contacts); writes the deformed meshes (OBJ) and a summary.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

crumple_ensure_packages
crumple_build -DCRUMPLE_BUILD_TESTS=OFF -DCRUMPLE_BUILD_SAMPLES=ON
out="${1:-$CRUMPLE_ROOT/demo-output}"
mkdir -p "$out"
"$CRUMPLE_BUILD_DIR/samples/crumple-wall-crash" --speed 15 --angle 0 --out "$out/head-on"
"$CRUMPLE_BUILD_DIR/samples/crumple-wall-crash" --speed 15 --angle 30 --out "$out/angle-30"
echo
echo "crumple demo: meshes and summaries are in $out/head-on and $out/angle-30"
