#!/usr/bin/env bash
# Determinism across compilers and SIMD: builds the perpdot CLI with gcc and with clang (no FMA
# contraction, no fast-math: see the top CMakeLists), and with gcc without SIMD (-DPERPDOT_SIMD=OFF:
# the contact and joint rows' portable 4-float lanes instead of SSE2), and checks that
# `perpdot run <scene>` prints the same state_hash with all three, for scenes that exercise
# stacking, friction, restitution, rotation, many contacts and joints (scalar and 4-wide: revolute
# in joint_grid, weld, prismatic and wheel in joint_rack, distance in distance_net, motor in
# motor_swarm). A
# difference names the scene and the three hashes. SCENE:N runs N steps (perpdot run --steps N,
# the scene's step count) instead of the scene's own, to keep the benchmark scenes short. The gcc
# build must also print the same hash on 2, 3, 4 and 8 workers (perpdot run --workers N), and with
# four contact lanes where it would use eight (PERPDOT_CONTACT_LANES=4).
#
# Snapshots too: for each scene of `snapshotScenes` (SCENE:N:K), every build saves the run at step
# K (`perpdot run --save-at`), the three files must be the same bytes, and every build loads every
# build's file (`--load`) and runs on to step N: all nine state hashes must equal the hash of the
# run that never saved.
#
#   tests/cross_compiler_hash.sh [GCC_BUILD_DIR [CLANG_BUILD_DIR [GCC_NO_SIMD_BUILD_DIR]]]
#
# Existing build dirs are reused (only the CLI target is built). PERPDOT_JOBS sets -j (default 2).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
gccDir="${1:-$root/build-hash-gcc}"
clangDir="${2:-$root/build-hash-clang}"
noSimdDir="${3:-$root/build-hash-gcc-nosimd}"
jobs="${PERPDOT_JOBS:-2}"
scenes=(single_box vertical_stack pyramid bouncing_balls friction_ramp rolling_disc spinning_box
        off_center_push card_house newtons_cradle tumbler rain dominoes chain suspension_bridge ragdoll
        joint_grid:200 joint_rack:150 distance_net:150
        motor_swarm:150)
snapshotScenes=(pyramid:200:100 vertical_stack:500:400 ragdoll:120:60 car:150:75 bullet_wall:20:2
                sensor_zone:160:80 tumbler:120:60 joint_grid:60:30)

build() {  # dir compiler simd
    cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$2" -DPERPDOT_SIMD="$3" \
        -DPERPDOT_BUILD_TESTS=OFF -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF >/dev/null
    cmake --build "$1" --target perpdot-cli -j"$jobs" >/dev/null
}
build "$gccDir" g++ ON
build "$clangDir" clang++ ON
build "$noSimdDir" g++ OFF

hashOf() {  # dir scene[:steps] [perpdot run flags...]
    local steps=()
    [[ "$2" == *:* ]] && steps=(--steps "${2#*:}")
    "$1/perpdot" run "${2%%:*}" "${steps[@]}" "${@:3}" | sed -n 's/.*state_hash=\([0-9a-f]*\).*/\1/p'
}
failed=0
for scene in "${scenes[@]}"; do
    g="$(hashOf "$gccDir" "$scene")"
    c="$(hashOf "$clangDir" "$scene")"
    n="$(hashOf "$noSimdDir" "$scene")"
    if [[ -z "$g" || "$g" != "$c" || "$g" != "$n" ]]; then
        echo "DIFFERENT $scene gcc=$g clang=$c gcc-no-simd=$n"
        failed=1
    else
        echo "same      $scene $g"
    fi
    # Threads: the gcc build on 2, 3, 4 and 8 workers (WorldDef::workerCount) gives the same world.
    for workers in 2 3 4 8; do
        t="$(hashOf "$gccDir" "$scene" --workers "$workers")"
        if [[ "$t" != "$g" ]]; then
            echo "DIFFERENT $scene with $workers workers: $t (1 worker: $g)"
            failed=1
        fi
    done
    # Contact lanes: four (SSE2) where the default is eight (AVX2 CPUs) gives the same world.
    f="$(PERPDOT_CONTACT_LANES=4 hashOf "$gccDir" "$scene")"
    if [[ "$f" != "$g" ]]; then
        echo "DIFFERENT $scene with four contact lanes: $f (default lanes: $g)"
        failed=1
    fi
done
snapDir="$(mktemp -d)"
trap 'rm -rf "$snapDir"' EXIT
dirs=("$gccDir" "$clangDir" "$noSimdDir")
names=(gcc clang gcc-no-simd)
for entry in "${snapshotScenes[@]}"; do
    IFS=: read -r scene steps saveAt <<<"$entry"
    for i in 0 1 2; do
        "${dirs[$i]}/perpdot" run "$scene" --steps "$steps" --save-at "$saveAt" "$snapDir/$scene.${names[$i]}" >/dev/null
    done
    hashes=("uninterrupted=$(hashOf "$gccDir" "$scene:$steps")")
    for i in 0 1 2; do
        cmp -s "$snapDir/$scene.gcc" "$snapDir/$scene.${names[$i]}" || { echo "DIFFERENT $scene snapshot bytes gcc vs ${names[$i]}"; failed=1; }
        for j in 0 1 2; do
            hashes+=("${names[$j]}<-${names[$i]}=$("${dirs[$j]}/perpdot" run "$scene" --steps "$steps" \
                --load "$snapDir/$scene.${names[$i]}" | sed -n 's/.*state_hash=\([0-9a-f]*\).*/\1/p')")
        done
    done
    if [[ "$(printf '%s\n' "${hashes[@]}" | sed 's/.*=//' | sort -u | wc -l)" != 1 || "${hashes[0]}" == *= ]]; then
        echo "DIFFERENT $scene restored: ${hashes[*]}"
        failed=1
    else
        echo "same      $scene saved at $saveAt, loaded by every build: ${hashes[0]#*=}"
    fi
done
exit $failed
