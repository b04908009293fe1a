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
run=()
if [ -z "${DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  run=(xvfb-run -a -s '-screen 0 1280x800x24')
fi
status=0
"${run[@]}" ctest --output-on-failure -j"$(nproc)" "$@" || status=$?
cd ..
# A short fuzz run of every parser (60 s in all; scripts/fuzz.sh, tests/fuzz/README.md), after
# ctest and whatever ctest said; either failing fails the script. FUZZ_TOTAL_SECONDS=0 skips it;
# the sanitizer run skips it (the fuzz targets have their own ASan + UBSan build).
fuzz_total="${FUZZ_TOTAL_SECONDS:-60}"
if [ -z "${DEMOPLAN_SANITIZE:-}" ] && [ "$fuzz_total" -gt 0 ]; then
  targets=()
  for f in tests/fuzz/fuzz_*.cpp; do t="${f##*/fuzz_}"; targets+=("${t%.cpp}"); done
  each=$((fuzz_total / ${#targets[@]})); [ "$each" -ge 1 ] || each=1
  ./scripts/fuzz.sh "$each" "${targets[@]}" || status=1
fi
exit "$status"
