#!/usr/bin/env bash
# Installs what is missing, builds, and runs demoplan on the bundled sample.
set -euo pipefail
cd "$(dirname "$0")"
./scripts/install-deps.sh
./scripts/build.sh
# Until the desktop application lands, the main job is the scene check on the bundled sample.
exec ./build/app/demoplan-cli check --task shelf_1 --robot panda --pose 0 "$@"
