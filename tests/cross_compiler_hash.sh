#!/usr/bin/env bash
# Determinism across compilers and SIMD: builds the perpdot CLI with gcc and with clang (no FMA
# contraction, no fast-math: see the top CMakeLists), and with gcc without SIMD (-DPERPDOT_SIMD=OFF:
# the contact and revolute joint rows' portable 4-float lanes instead of SSE2), and checks that
# `perpdot run <scene>` prints the same state_hash with all three, for scenes that exercise
# stacking, friction, restitution, rotation, many contacts and joints (scalar and 4-wide). A
# difference names the scene and the three hashes. SCENE:N runs N steps (perpdot run --steps N,
# the scene's step count) instead of the scene's own, to keep the benchmark scenes short.
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
        joint_grid:200)

build() {  # dir compiler simd
    cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$2" -DPERPDOT_SIMD="$3" \
        -DPERPDOT_BUILD_TESTS=OFF -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF >/dev/null
    cmake --build "$1" --target perpdot-cli -j"$jobs" >/dev/null
}
build "$gccDir" g++ ON
build "$clangDir" clang++ ON
build "$noSimdDir" g++ OFF

hashOf() {  # dir scene[:steps]
    local steps=()
    [[ "$2" == *:* ]] && steps=(--steps "${2#*:}")
    "$1/perpdot" run "${2%%:*}" "${steps[@]}" | sed -n 's/.*state_hash=\([0-9a-f]*\).*/\1/p'
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
done
exit $failed
