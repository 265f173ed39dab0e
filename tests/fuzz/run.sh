#!/usr/bin/env bash
# Builds the libFuzzer harnesses with clang (PERPDOT_FUZZ) and runs each for half of SECONDS.
#   tests/fuzz/run.sh [SECONDS] [BUILD_DIR]      (default 60 s, build-fuzz)
# New inputs go to BUILD_DIR/corpus/<harness>; the checked-in seeds in tests/fuzz/corpus are only
# read. A crash leaves crash-* / leak-* / timeout-* files in BUILD_DIR and fails the script.
# Longer run (docs/reliability.md): tests/fuzz/run.sh 600
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
seconds="${1:-60}"
build="${2:-$root/build-fuzz}"
jobs="${PERPDOT_JOBS:-2}"

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DPERPDOT_FUZZ=ON \
    -DPERPDOT_BUILD_TESTS=OFF -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --target fuzz_scene fuzz_snapshot -j"$jobs" >/dev/null

for harness in scene snapshot; do
    corpus="$build/corpus/$harness"
    mkdir -p "$corpus"
    echo "== fuzz_$harness for $((seconds / 2)) s"
    "$build/tests/fuzz/fuzz_$harness" -max_total_time=$((seconds / 2)) -max_len=8192 -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$build/" -print_final_stats=1 "$corpus" "$root/tests/fuzz/corpus/$harness" 2>&1 |
        grep -E "^(stat::number_of_executed_units|stat::new_units_added|Done [0-9]+ runs|==[0-9]+==ERROR|SUMMARY|.*(crash|leak|timeout)-)" || true
    if compgen -G "$build/crash-*" >/dev/null || compgen -G "$build/leak-*" >/dev/null || compgen -G "$build/timeout-*" >/dev/null; then
        echo "fuzz_$harness found a failing input:" "$build"/crash-* "$build"/leak-* "$build"/timeout-* 2>/dev/null
        exit 1
    fi
done
