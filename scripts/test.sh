#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, and runs every test.
#   1. release build with -Werror, the whole ctest suite
#   2. ASan + UBSan build of the test suite
# Prints the ctest summary of each; exits non-zero on the first failure.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${PERPDOT_JOBS:-$(nproc)}

bash third_party/install-deps.sh

echo "== release build and tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPERPDOT_WERROR=ON
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs"

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPERPDOT_SANITIZE=ON -DPERPDOT_WERROR=ON \
  -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF
cmake --build build-asan -j"$jobs"
ctest --test-dir build-asan --output-on-failure -j"$jobs"
