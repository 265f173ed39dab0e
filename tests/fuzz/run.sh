#!/usr/bin/env bash
# CI fuzz smoke: builds the libFuzzer harnesses with clang (PERPDOT_FUZZ) and runs each for a fixed
# number of inputs from a fixed seed — the same work on every run, never open-ended exploration
# (that is tests/fuzz/explore.sh).
#   tests/fuzz/run.sh [RUNS] [SEED] [BUILD_DIR]      (default 20000 inputs per harness, seed 1, build-fuzz)
# Starts from the checked-in seeds and findings (only read); new inputs go to a scratch corpus
# BUILD_DIR/smoke/<harness>, emptied first. Fails when a harness does not build or start, exits
# non-zero, does not report its runs, or leaves a crash-, leak-, timeout- or oom- file. The
# timeout is wall-clock, hence generous (600 s per input; every input takes well under 1 s of
# CPU, yet inputs were seen waiting 155 s for it on the loaded 2-core machine), so a loaded machine
# cannot make it fail.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
runs="${1:-20000}"
seed="${2:-1}"
build="${3:-$root/build-fuzz}"
jobs="${PERPDOT_JOBS:-2}"
harnesses=(scene snapshot api)

cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ -DPERPDOT_FUZZ=ON \
    -DPERPDOT_BUILD_TESTS=OFF -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" --target "${harnesses[@]/#/fuzz_}" -j"$jobs" >/dev/null

for harness in "${harnesses[@]}"; do
    scratch="$build/smoke/$harness"
    rm -rf "$scratch" "$build/smoke/$harness"-*
    mkdir -p "$scratch"
    log="$build/smoke/$harness.log"
    echo "== fuzz_$harness: $runs inputs, seed $seed"
    # The checked-in seeds, and the findings where this harness has any (git keeps no empty folder).
    inputs=("$root/tests/fuzz/corpus/$harness")
    [ -d "$root/tests/fuzz/findings/$harness" ] && inputs+=("$root/tests/fuzz/findings/$harness")
    status=0
    "$build/tests/fuzz/fuzz_$harness" -seed="$seed" -runs="$runs" -max_len=8192 -timeout=600 -rss_limit_mb=2048 \
        -artifact_prefix="$build/smoke/$harness-" -print_final_stats=1 \
        "$scratch" "${inputs[@]}" >"$log" 2>&1 || status=$?
    grep -E "^(stat::number_of_executed_units|stat::new_units_added|Done [0-9]+ runs)" "$log" || true
    # Failures only: libFuzzer also writes slow-unit-* files, which a busy machine can cause.
    artifacts=$(for kind in crash leak timeout oom; do compgen -G "$build/smoke/$harness-$kind-*"; done || true)
    if [ "$status" -ne 0 ] || [ -n "$artifacts" ] || ! grep -q "^Done $runs runs" "$log"; then
        echo "fuzz_$harness FAILED (exit status $status)${artifacts:+, failing input: $artifacts}; log $log:"
        grep -E "ERROR|SUMMARY|Assert|assert|terminate|==[0-9]+==" "$log" | head -20 || tail -20 "$log"
        exit 1
    fi
done
