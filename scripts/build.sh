#!/usr/bin/env bash
# Configures (once) and builds demoplan into build/ with Ninja and ccache.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_TYPE="${BUILD_TYPE:-RelWithDebInfo}"
export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
# Paths relative to the checkout, so every clone of the repository (CI's too) shares the cache.
export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}"
export CCACHE_NOHASHDIR=1
# BUILD_DIR (default build) and DEMOPLAN_SANITIZE (e.g. address,undefined) select another build.
BUILD_DIR="${BUILD_DIR:-build}"
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE" \
    -DDEMOPLAN_SANITIZE="${DEMOPLAN_SANITIZE:-}" >/dev/null
fi
# Two cores, but FCL-heavy translation units use ~1 GB each: -j2 is safe on 24 GB.
cmake --build "$BUILD_DIR" -- -j"$(nproc)"
