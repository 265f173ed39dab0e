#!/usr/bin/env bash
# The README's test command (and what CI runs through .ci/run): installs what is missing, builds,
# and runs every check:
#   1. release build with -Werror, the whole ctest suite (it replays every checked-in fuzz seed and
#      finding, tests/fuzz/CMakeLists.txt), the API reference (Doxygen, no warnings)
#   2. AddressSanitizer + UndefinedBehaviorSanitizer build, the whole ctest suite again
#   3. ThreadSanitizer: the threaded stages on a game's task system (clang, -fsanitize=thread)
#   4. determinism across compilers and threads: gcc and clang builds print the same state_hash,
#      and so does the gcc build on 2, 3, 4 and 8 workers
#   5. determinism across CPUs: ARM64 (cross-built, run under qemu-user) and 32-bit x86 builds, each
#      linking a Box2D built without fused multiply-adds, print the x86-64 state_hash on every
#      scene, continue each other's snapshots, and pass their unit tests (under qemu: a subset; i386
#      runs natively where the kernel runs 32-bit programs, else under qemu-i386)
#   6. a fixed libFuzzer smoke of the scene, snapshot and API harnesses (seed 1, 20000 inputs each;
#      open-ended exploration is tests/fuzz/explore.sh, never CI)
#   7. clang-tidy with the checked-in .clang-tidy
# Exits non-zero on the first failure; ends with both ctest summaries.
set -euo pipefail
cd "$(dirname "$0")/.."
export PERPDOT_JOBS=${PERPDOT_JOBS:-$(nproc)}
jobs=$PERPDOT_JOBS
log=$(mktemp -d)

bash third_party/install-deps.sh

echo "== release build (-Werror) and tests"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPERPDOT_WERROR=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
cmake --build build -j"$jobs"
ctest --test-dir build --output-on-failure -j"$jobs" | tee "$log/release"
cmake --build build --target perpdot-docs

echo "== AddressSanitizer + UndefinedBehaviorSanitizer build and tests"
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DPERPDOT_SANITIZE=ON -DPERPDOT_WERROR=ON \
  -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF
cmake --build build-asan -j"$jobs"
ctest --test-dir build-asan --output-on-failure -j"$jobs" | tee "$log/asan"

echo "== ThreadSanitizer (clang): every threaded stage on a game's std::threads (tests/workers_test.cpp)"
cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DPERPDOT_TSAN=ON \
  -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF
cmake --build build-tsan -j"$jobs" --target perpdot-tests
TSAN_OPTIONS=halt_on_error=1 build-tsan/tests/perpdot-tests --gtest_filter='Workers.AGames*:Workers.ATask*' \
  | tee "$log/tsan"
# A filter that matches nothing would pass vacuously: at least one test must have run.
grep -Eq '^\[  PASSED  \] [1-9][0-9]* test' "$log/tsan" || { echo "ThreadSanitizer: the filter ran no test"; exit 1; }

echo "== gcc vs clang state_hash, and 1 vs 2, 3, 4, 8 workers"
bash tests/cross_compiler_hash.sh

echo "== x86-64 vs ARM64 (qemu) vs i386 state_hash, snapshots across CPUs, cross-built unit tests"
time bash tests/cross_arch_hash.sh

echo "== fuzz smoke (fixed seed and input count)"
bash tests/fuzz/run.sh

echo "== clang-tidy"
bash tests/clang_tidy.sh build

echo "== summary"
echo "release: $(grep 'tests passed' "$log/release")"
echo "asan:    $(grep 'tests passed' "$log/asan")"
