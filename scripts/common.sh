#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 The Crumple authors
# SPDX-License-Identifier: MIT
# Shared by test.sh and demo.sh: Debian packages, configure, build.
set -euo pipefail

CRUMPLE_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
CRUMPLE_BUILD_DIR="${CRUMPLE_BUILD_DIR:-$CRUMPLE_ROOT/build-release}"
CRUMPLE_JOBS="${CRUMPLE_JOBS:-$(nproc 2>/dev/null || echo 2)}"

# Debian packages every build needs (the optional adapters switch themselves off without theirs; tetgen is
# the optional command-line tetrahedralizer that fem surface import runs; chromium opens crash reports in a
# test).
CRUMPLE_PACKAGES=(cmake make g++ pkg-config libeigen3-dev catch2 libbullet-dev libode-dev libassimp-dev
    libegl-dev libgl-dev libegl-mesa0 libgl1-mesa-dri libstb-dev tetgen nlohmann-json3-dev chromium)

crumple_ensure_packages() {
    local missing=()
    for package in "${CRUMPLE_PACKAGES[@]}" "$@"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
    done
    [ "${#missing[@]}" -eq 0 ] && return 0
    if [ "$(id -u)" -eq 0 ]; then
        echo "crumple: installing Debian packages: ${missing[*]}"
        export DEBIAN_FRONTEND=noninteractive
        apt-get update -qq
        apt-get install -y -qq --no-install-recommends "${missing[@]}"
    else
        echo "crumple: missing Debian packages. Run as root:" >&2
        echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
        exit 1
    fi
}

# crumple_build [extra cmake args...]: configure and build in Release.
crumple_build() {
    cmake -S "$CRUMPLE_ROOT" -B "$CRUMPLE_BUILD_DIR" -DCMAKE_BUILD_TYPE=Release "$@"
    cmake --build "$CRUMPLE_BUILD_DIR" --parallel "$CRUMPLE_JOBS"
}
