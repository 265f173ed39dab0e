#!/usr/bin/env bash
# Open-ended exploration (never in CI): runs one libFuzzer harness for SECONDS, growing its corpus.
#   tests/fuzz/explore.sh HARNESS SECONDS [BUILD_DIR]     HARNESS: scene | snapshot | api
# Builds like tests/fuzz/run.sh (clang, ASan + UBSan + coverage, BUILD_DIR default build-fuzz).
# The growing corpus is BUILD_DIR/explore/HARNESS (the checked-in seeds are only read); a failing
# input is written to BUILD_DIR/explore/HARNESS-crash-* (leak-, timeout-, oom-) and the script
# exits non-zero. Whatever it finds goes to tests/fuzz/findings/HARNESS/ with its fix, so ctest
# replays it from then on (tests/fuzz/CMakeLists.txt). Ends with libFuzzer's executed-unit count.
# libFuzzer's -timeout is wall-clock, so it is 600 s per input: under `nice -n 19` on the loaded
# 2-core machine, inputs that run in 0.1 s of CPU were reported after 15 s and even 155 s.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
harness="${1:?usage: explore.sh scene|snapshot|api SECONDS [BUILD_DIR]}"
seconds="${2:?usage: explore.sh scene|snapshot|api SECONDS [BUILD_DIR]}"
build="${3:-$root/build-fuzz}"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DPERPDOT_FUZZ=ON \
    -DPERPDOT_BUILD_TESTS=OFF -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --target "fuzz_$harness" -j"${PERPDOT_JOBS:-2}" >/dev/null

corpus="$build/explore/$harness"
mkdir -p "$corpus"
echo "== fuzz_$harness for $seconds s, started $(date -u +%FT%TZ)"
status=0
"$build/tests/fuzz/fuzz_$harness" -max_total_time="$seconds" -max_len=8192 -timeout=600 -rss_limit_mb=2048 \
    -artifact_prefix="$build/explore/$harness-" -print_final_stats=1 "$corpus" "$root/tests/fuzz/corpus/$harness" \
    >"$build/explore/$harness.log" 2>&1 || status=$?
grep -E "^(stat::number_of_executed_units|stat::new_units_added|stat::average_exec_per_sec|Done [0-9]+ runs|SUMMARY)" \
    "$build/explore/$harness.log" || true
echo "== ended $(date -u +%FT%TZ), libFuzzer exit status $status (log: $build/explore/$harness.log)"
failing=$(compgen -G "$build/explore/$harness-crash-*"; compgen -G "$build/explore/$harness-leak-*";
          compgen -G "$build/explore/$harness-timeout-*"; compgen -G "$build/explore/$harness-oom-*") || true
if [ "$status" -ne 0 ] || [ -n "$failing" ]; then
    echo "fuzz_$harness found a failing input (libFuzzer's slow-unit-* files are only slow):" $failing
    exit 1
fi
