#!/usr/bin/env bash
# Determinism across compilers and SIMD: builds the perpdot CLI with gcc and with clang (no FMA
# contraction, no fast-math: see the top CMakeLists), and with gcc without SIMD (-DPERPDOT_SIMD=OFF:
# the contact and joint rows' portable 4-float lanes instead of SSE2), and checks that
# `perpdot run <scene>` prints the same state_hash with all three for every scene of
# tests/hash_common.sh. A difference names the scene and the three hashes. The gcc build must also
# print the same hash on 2, 3, 4 and 8 workers (perpdot run --workers N), and with four contact
# lanes where it would use eight (PERPDOT_CONTACT_LANES=4).
#
# Snapshots too (compareSnapshots): each build's snapshot of a run is the same bytes, and every
# build continues every build's snapshot to the hash of the run that never saved.
#
#   tests/cross_compiler_hash.sh [GCC_BUILD_DIR [CLANG_BUILD_DIR [GCC_NO_SIMD_BUILD_DIR]]]
#
# Existing build dirs are reused (only the CLI target is built). PERPDOT_JOBS sets -j (default 2).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/tests/hash_common.sh"
gccDir="${1:-$root/build-hash-gcc}"
clangDir="${2:-$root/build-hash-clang}"
noSimdDir="${3:-$root/build-hash-gcc-nosimd}"
jobs="${PERPDOT_JOBS:-2}"
build() {  # dir compiler simd
    cmake -S "$root" -B "$1" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$2" -DPERPDOT_SIMD="$3" \
        -DPERPDOT_BUILD_TESTS=OFF -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF >/dev/null
    cmake --build "$1" --target perpdot-cli -j"$jobs" >/dev/null
}
build "$gccDir" g++ ON
build "$clangDir" clang++ ON
build "$noSimdDir" g++ OFF

failed=0
for scene in "${scenes[@]}"; do
    g="$(hashOf "$gccDir/perpdot" "$scene")"
    c="$(hashOf "$clangDir/perpdot" "$scene")"
    n="$(hashOf "$noSimdDir/perpdot" "$scene")"
    if [[ -z "$g" || "$g" != "$c" || "$g" != "$n" ]]; then
        echo "DIFFERENT $scene gcc=$g clang=$c gcc-no-simd=$n"
        failed=1
    else
        echo "same      $scene $g"
    fi
    # Threads: the gcc build on 2, 3, 4 and 8 workers (WorldDef::workerCount) gives the same world.
    for workers in 2 3 4 8; do
        t="$(hashOf "$gccDir/perpdot" "$scene" --workers "$workers")"
        if [[ "$t" != "$g" ]]; then
            echo "DIFFERENT $scene with $workers workers: $t (1 worker: $g)"
            failed=1
        fi
    done
    # Contact lanes: four (SSE2) where the default is eight (AVX2 CPUs) gives the same world.
    f="$(PERPDOT_CONTACT_LANES=4 hashOf "$gccDir/perpdot" "$scene")"
    if [[ "$f" != "$g" ]]; then
        echo "DIFFERENT $scene with four contact lanes: $f (default lanes: $g)"
        failed=1
    fi
done
compareSnapshots gcc="$gccDir/perpdot" clang="$clangDir/perpdot" gcc-no-simd="$noSimdDir/perpdot"
exit $failed
