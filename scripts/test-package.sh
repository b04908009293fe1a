#!/usr/bin/env bash
# The package test (ctest: package_installs_and_runs): builds the .deb with CPack, unpacks it
# into a temporary root, and runs the unpacked programs from there, far from the source tree:
# `check` must load the unpacked benchmark data, `plan` must solve shelf_0, `board` must run (in
# the private demoplan-cli-video), the GUI must open the unpacked sample; lintian must report no
# error (accepted warnings: packaging/README.md).
set -euo pipefail
build="$(cd "${1:?usage: test-package.sh BUILD_DIR}" && pwd)"
root="$(mktemp -d)"
trap 'rm -rf "$root"' EXIT
cd "$build"
cpack -G DEB -B "$root/out" >/dev/null
deb="$(ls "$root"/out/demoplan_*.deb)"
dpkg-deb -x "$deb" "$root/fs"
cd "$root"
cli="$root/fs/usr/bin/demoplan-cli"

out="$("$cli" check --task shelf_0 --robot panda --pose 0 --seconds 0.1 2>&1)"
# (Here-strings, not pipes: `head` and `grep -q` stop reading early, and with pipefail the
# writer's SIGPIPE would fail the script without a word; it did once under a loaded ctest.)
head -1 <<<"$out"
grep -q "($root/fs/usr/share/demoplan/gtamp)" <<<"$out" || { echo "FAIL: check did not load the unpacked data" >&2; exit 1; }

"$cli" plan --task shelf_0 --robot panda --pose 0 --seed 1 --out "$root/path.json" 2>"$root/plan.log" || {
  cat "$root/plan.log" >&2; echo "FAIL: the unpacked plan failed" >&2; exit 1; }
grep -q "validator (benchmark subgoals): valid" "$root/plan.log" || { cat "$root/plan.log" >&2; exit 1; }
grep "validator" "$root/plan.log"

# A video command runs in the private demoplan-cli-video, found from the unpacked demoplan-cli.
"$cli" board --out "$root/board.json" --image "$root/board.png" 2>"$root/board.log" || {
  cat "$root/board.log" >&2; echo "FAIL: the unpacked board command failed" >&2; exit 1; }
[ -s "$root/board.png" ] || { echo "FAIL: board wrote no page" >&2; exit 1; }
echo "board ran in $(cd "$root/fs" && ls usr/lib/demoplan/demoplan-cli-video)"

if [ -n "${DISPLAY:-}" ] && [ -x "$root/fs/usr/bin/demoplan" ]; then
  "$root/fs/usr/bin/demoplan" --sample --screenshot "$root/shot.png" --screenshot-delay 500 >"$root/gui.log" 2>&1 || {
    cat "$root/gui.log" >&2; echo "FAIL: the unpacked GUI did not open the sample" >&2; exit 1; }
  [ -s "$root/shot.png" ] || { echo "FAIL: no screenshot" >&2; exit 1; }
  echo "GUI opened the unpacked sample"
fi

command -v lintian >/dev/null || { echo "FAIL: lintian is not installed (scripts/install-deps.sh installs it)" >&2; exit 1; }
lint="$(lintian "$deb" 2>&1 | grep -v 'running with root privileges' || true)"
[ -n "$lint" ] && echo "$lint"
if grep -q '^E:' <<<"$lint"; then echo "FAIL: lintian reports errors" >&2; exit 1; fi
echo "package ok: $(basename "$deb"), $(du -h "$deb" | cut -f1)"
