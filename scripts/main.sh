#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, and runs the main job -- the
# default demo scene (pyramid) headless, writing PNG frames and a contact sheet to out/pyramid/,
# followed by its cross-check summary against Box2D 2.4.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${PERPDOT_JOBS:-$(nproc)}
scene=${1:-pyramid}

bash third_party/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$jobs" --target perpdot-demo perpdot-cli
build/demos/perpdot-demo --headless "$scene" --frames 120 --every 5 --size 640x480 --out "out/$scene"
echo "frames and contact sheet: out/$scene/"
