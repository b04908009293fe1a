#!/usr/bin/env bash
# Builds the libFuzzer targets (tests/fuzz/fuzz_*.cpp) into build-fuzz/ with clang 14, ASan and
# UBSan, and runs each for SECONDS (default 600) from its seed corpus (tests/fuzz/corpus/<target>).
# Exits 1 when a target finds a crash, a hang, a leak or a sanitizer report.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]     e.g. scripts/fuzz.sh 60 project urdf
#
# New corpus inputs go to a temporary folder (the seed corpora in the repository are not
# changed); crash inputs are kept there (printed at the end): put each in
# tests/data/fuzz-regressions/<target>/ once the parser is fixed (tests/fuzz/README.md).
# FUZZ_KEEP_GOING=1 runs each target in libFuzzer's fork mode, which goes on after a crash and
# keeps every crash input. FUZZ_OUT=DIR keeps the run's files in DIR. FUZZ_JOBS: build jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH="${1:-600}"
[ $# -gt 0 ] && shift
BUILD_DIR="${FUZZ_BUILD_DIR:-build-fuzz}"

export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}" CCACHE_BASEDIR="${CCACHE_BASEDIR:-$PWD}" CCACHE_NOHASHDIR=1
if [ ! -f "$BUILD_DIR/build.ninja" ]; then
  CC=clang-14 CXX=clang++-14 cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DDEMOPLAN_FUZZ=ON >/dev/null
fi
cmake --build "$BUILD_DIR" -- -j"${FUZZ_JOBS:-$(nproc)}"

if [ $# -gt 0 ]; then
  targets=("$@")
else
  targets=()
  for f in tests/fuzz/fuzz_*.cpp; do t="${f##*/fuzz_}"; targets+=("${t%.cpp}"); done
fi

# Longest input a target tries: a little more than its largest seed.
max_len() {
  case "$1" in
    task) echo 49152 ;;
    urdf) echo 20480 ;;
    bop_csv | hand_detections | camera | camera_yaml | camera_xml) echo 4096 ;;
    *) echo 8192 ;;
  esac
}
dict() {
  case "$1" in
    urdf | srdf | camera_xml) echo "-dict=tests/fuzz/xml.dict" ;;
    bop_csv | camera_yaml) ;;
    *) echo "-dict=tests/fuzz/json.dict" ;;
  esac
}

OUT="${FUZZ_OUT:-$(mktemp -d "${TMPDIR:-/tmp}/demoplan-fuzz.XXXXXX")}"
mkdir -p "$OUT"
# Leaks are findings too; UBSan reports abort (the targets are built with -fno-sanitize-recover).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
failed=()
total=0
for t in "${targets[@]}"; do
  bin="$BUILD_DIR/tests/fuzz/fuzz_$t"
  [ -x "$bin" ] || { echo "fuzz: no target fuzz_$t" >&2; exit 2; }
  mkdir -p "$OUT/$t/corpus" "$OUT/$t/crashes" "$OUT/$t/tmp"
  cp tests/fuzz/corpus/"$t"/* "$OUT/$t/corpus/"
  mode=()
  [ "${FUZZ_KEEP_GOING:-0}" = 1 ] && mode=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
  rc=0
  # shellcheck disable=SC2046
  # The targets' input files go to TMPDIR: the run's folder, also when a crash skips their cleanup.
  TMPDIR="$OUT/$t/tmp" "$bin" "${mode[@]}" -max_total_time="$SECONDS_EACH" -max_len="$(max_len "$t")" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$OUT/$t/crashes/" $(dict "$t") "$OUT/$t/corpus" >"$OUT/$t/log" 2>&1 || rc=$?
  # Executions: libFuzzer's final statistics, or in fork mode the last status line's count.
  execs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$OUT/$t/log" | grep -o '[0-9]*$' | tail -1 || true)
  [ -n "$execs" ] || execs=$(grep -oE '^#[0-9]+' "$OUT/$t/log" | tail -1 | tr -d '#' || true)
  execs=${execs:-0}
  total=$((total + execs))
  crashes=$(find "$OUT/$t/crashes" -type f | wc -l)
  printf 'fuzz_%-16s %4ss %10s executions  %s crash inputs  exit %s\n' "$t" "$SECONDS_EACH" "$execs" "$crashes" "$rc" >&2
  if [ "$rc" -ne 0 ] || [ "$crashes" -ne 0 ]; then
    failed+=("$t")
    grep -m1 -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error|breaks the one-line' "$OUT/$t/log" >&2 || true
  fi
done
echo "fuzz: ${#targets[@]} targets, $total executions in all; logs, corpora and crash inputs in $OUT" >&2
if [ ${#failed[@]} -gt 0 ]; then
  echo "fuzz: FAILED: ${failed[*]}" >&2
  exit 1
fi
