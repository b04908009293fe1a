#!/usr/bin/env bash
# Installs what is missing, builds, and runs demoplan on the bundled sample.
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
./scripts/build.sh
# The desktop application on the bundled sample (or on the project given as an argument).
[ $# -eq 0 ] && set -- --sample
if [ -z "${DISPLAY:-}" ] && [ -z "${WAYLAND_DISPLAY:-}" ] && command -v xvfb-run >/dev/null; then
  # No display (a headless machine): render the window once under Xvfb and save a picture of it.
  echo "run.sh: no display; rendering demoplan under Xvfb into build/demoplan-window.png" >&2
  exec xvfb-run -a -s '-screen 0 1280x800x24' ./build/app/demoplan --screenshot build/demoplan-window.png "$@"
fi
exec ./build/app/demoplan "$@"
