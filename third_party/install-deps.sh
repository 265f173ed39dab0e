#!/usr/bin/env bash
# Installs every system package perpdot needs to build, test and run its demos,
# from Debian 12's archive only. Safe to re-run: apt-get skips what is present.
set -euo pipefail
packages=(
  build-essential cmake git pkg-config
  clang clang-tidy libclang-rt-14-dev   # gcc-vs-clang determinism, clang-tidy, libFuzzer
  libbox2d-dev            # collision: b2DynamicTree, b2Collide*, and b2World for cross-checks
  libtbb-dev              # the default workers of a threaded step (WorldDef::workerCount)
  nlohmann-json3-dev      # scene files
  libgtest-dev libgmock-dev libbenchmark-dev
  libsdl2-dev libsdl2-image-dev libimgui-dev   # demo viewer and headless PNG frames
  gnuplot-nox             # cross-check plots
  doxygen                 # API reference (perpdot-docs), warnings fail CI
  xvfb xauth              # windowed viewer test
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "install-deps: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi
