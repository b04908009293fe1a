#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test.
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
# --sanitize: the same tests on a build with AddressSanitizer and UndefinedBehaviorSanitizer
# (build-sanitize/). Leak checking is off: Qt and the GL drivers keep allocations until exit.
if [ "${1:-}" = "--sanitize" ]; then
  shift
  export BUILD_DIR=build-sanitize DEMOPLAN_SANITIZE=address,undefined
  export ASAN_OPTIONS="detect_leaks=0:abort_on_error=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
fi
./scripts/build.sh
cd "${BUILD_DIR:-build}"
# GL and widget tests need an X server; xvfb-run provides one on a headless machine.
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  exec xvfb-run -a -s '-screen 0 1280x800x24' ctest --output-on-failure -j"$(nproc)" "$@"
fi
exec ctest --output-on-failure -j"$(nproc)" "$@"
