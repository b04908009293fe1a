#!/usr/bin/env bash
# Installs the Debian 12 packages demoplan builds and tests with; only the missing ones.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config ccache git
  libtinyxml-dev libconsole-bridge-dev
  libeigen3-dev libfcl-dev libccd-dev libassimp-dev liburdfdom-dev liburdfdom-headers-dev
  nlohmann-json3-dev libnanoflann-dev libcli11-dev libqhull-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  qt6-base-dev qt6-base-dev-tools libqt6opengl6-dev libqt6openglwidgets6
  libgl-dev libegl-dev libgl1-mesa-dri mesa-utils
  libopencv-dev libopencv-contrib-dev ffmpeg
  # OMPL's planners beside ours (bench-segments); its ompl_benchmark_statistics reads bench --ompl-log
  libompl-dev ompl-demos
  xvfb xauth
  # the package test: lintian judges the .deb that CPack builds
  lintian
  # the parsers' fuzz targets (scripts/fuzz.sh, tests/fuzz): clang 14 and its libFuzzer
  clang-14 libfuzzer-14-dev
  # the placement search as a Slurm job array (packaging/slurm, tests/slurm): a one-node cluster
  munge slurmctld slurmd slurm-client python3
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "Installing: ${missing[*]}" >&2
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
