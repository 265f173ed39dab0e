#!/usr/bin/env bash
# Determinism across CPUs: the perpdot CLI and unit tests cross-built for ARM64 (g++-aarch64-linux-gnu,
# run under qemu-aarch64) and for 32-bit x86 (g++-i686-linux-gnu with SSE2 arithmetic, run
# natively where the kernel runs 32-bit programs, else under qemu-i386), each linking the Box2D
# that third_party/box2d-deterministic.sh builds for it, must
#   - print the x86-64 gcc build's state_hash for every scene of tests/hash_common.sh,
#   - write snapshots of the same bytes, and continue every build's snapshot to the hash of the
#     x86-64 run that never saved (compareSnapshots, across x86-64, ARM64 and i386),
#   - on i386, print the same hash on 2 and 4 oneTBB workers (--workers N; natively only, see below);
#   - pass unit tests: on native i386 all of them (the tests that start the CLI start the i386
#     one); under qemu, on ARM64 and on i386, the subset `qemuTests` below.
# 32-bit x86 under qemu: some x86-64 kernels are built without IA32 emulation (CI's, among them),
# and there a 32-bit program fails with 'Exec format error'. A probe program tells; then i386 is
# checked as ARM64 is, its workers through the game's task system.
# Threads on ARM64: oneTBB's workers have been seen to hang under qemu-user before they start (a
# limitation of the emulator, not of ARM64), and a hang would stall CI, so ARM64 threads are checked through a game's task system on
# std::threads (WorldDef::enqueueTask; the Workers.AGames* and Workers.ATask* tests), which qemu
# runs: each scene of tests/workers_test.cpp stepped on three threads gives the one-worker world.
#
#   tests/cross_arch_hash.sh [X86_64_GCC_BUILD_DIR]
#
# The x86-64 build dir is the one of tests/cross_compiler_hash.sh (reused; built if absent). The
# cross builds go to build-arch-aarch64 and build-arch-i386, Box2D to build-box2d; all are reused.
# PERPDOT_JOBS sets -j (default 2).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/tests/hash_common.sh"
hostDir="${1:-$root/build-hash-gcc}"
jobs="${PERPDOT_JOBS:-2}"
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

# Unit tests under qemu: those that start no other program (the CLI and stress tests start
# the perpdot command: an ARM64 program started by a test needs the kernel to hand it to qemu,
# binfmt_misc, which CI machines lack) and use no oneTBB workers, chosen to fit the CI budget
# (qemu runs perpdot about 20 times slower than the CPU): the portable sin, cos, atan2 and exp
# bit for bit (their accuracy tests compare with long double, software-emulated on ARM64: they run
# on x86-64 and native i386), threads on a game's task system, determinism and snapshots, the SIMD lanes
# against scalar rows, the numerics, Box2D's collision through perpdot (shapes, casts, time of
# impact), and the dynamics checked against analytic results and Box2D's b2World.
# SnapshotRollback (1,800 restore points) would take two thirds of the time: it runs on x86-64 and
# native i386, and snapshots across CPUs are compareSnapshots' job.
qemuTests='PortableMath.SameBitsOnEveryCpu:Workers.AGames*:Workers.ATask*:Determinism.*:Snapshot.*:GearPulleySnapshot.*'
qemuTests+=':ContactSolverWide.*:JointSolverWide.*:Numerics.*:Capsule.*:ShapeCast.*:TimeOfImpact.*:Mass.*'
qemuTests+=':Contact.*:BoxOnGround.*:Dynamics.*:CrosscheckPhysics.*:PairSet.*:RadixSort.*:StaticTree.*'

# i386Emulator: empty where this kernel runs 32-bit x86 programs, else qemu-i386; i386Tests: the
# unit tests i386 runs (all natively, the qemu subset under qemu).
probe="$(mktemp -d)"
printf 'int main(void) { return 0; }\n' >"$probe/probe.c"
i686-linux-gnu-gcc "$probe/probe.c" -o "$probe/probe"
i386Emulator=()
i386Tests=()
"$probe/probe" 2>/dev/null || { i386Emulator=(qemu-i386); i386Tests=(--gtest_filter="$qemuTests"); }
rm -rf "$probe"

buildFor() {  # arch toolchain-file [cmake flags...]
    local prefix
    prefix="$(bash "$root/third_party/box2d-deterministic.sh" "$1")"
    cmake -S "$root" -B "$root/build-arch-$1" -DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/$2" "${@:3}" \
        -DCMAKE_BUILD_TYPE=Release -DPERPDOT_BOX2D_PREFIX="$prefix" "${launcher[@]}" \
        -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF -DPERPDOT_BUILD_DOCS=OFF -DPERPDOT_INSTALL=OFF >/dev/null
    cmake --build "$root/build-arch-$1" --target perpdot-cli perpdot-tests -j"$jobs" >/dev/null
}
if [[ ! -x "$hostDir/perpdot" ]]; then
    cmake -S "$root" -B "$hostDir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER=g++ "${launcher[@]}" \
        -DPERPDOT_BUILD_TESTS=OFF -DPERPDOT_BUILD_DEMOS=OFF -DPERPDOT_BUILD_BENCH=OFF >/dev/null
    cmake --build "$hostDir" --target perpdot-cli -j"$jobs" >/dev/null
fi
buildFor aarch64 aarch64-linux-gnu.cmake
[[ ${#i386Emulator[@]} -eq 0 ]] || echo "this kernel runs no 32-bit x86 program: i386 runs under qemu-i386"
buildFor i386 i686-linux-gnu.cmake -DCMAKE_CROSSCOMPILING_EMULATOR="${i386Emulator[*]}"
host="$hostDir/perpdot"
arm="qemu-aarch64 $root/build-arch-aarch64/perpdot"
i386="${i386Emulator[*]:+${i386Emulator[*]} }$root/build-arch-i386/perpdot"

failed=0
matched=0
for scene in "${scenes[@]}"; do
    x="$(hashOf "$host" "$scene")"
    a="$(hashOf "$arm" "$scene")"
    i="$(hashOf "$i386" "$scene")"
    if [[ -z "$x" || "$x" != "$a" || "$x" != "$i" ]]; then
        echo "DIFFERENT $scene x86-64=$x aarch64=$a i386=$i"
        failed=1
    else
        echo "same      $scene $x"
        matched=$((matched + 1))
    fi
    [[ ${#i386Emulator[@]} -gt 0 ]] && continue
    for workers in 2 4; do
        t="$(hashOf "$i386" "$scene" --workers "$workers")"
        [[ "$t" == "$i" ]] || { echo "DIFFERENT $scene on i386 with $workers workers: $t (1 worker: $i)"; failed=1; }
    done
done
echo "$matched of ${#scenes[@]} scenes give the x86-64 state_hash on aarch64 and i386"
compareSnapshots x86-64="$host" aarch64="$arm" i386="$i386"

echo "== ARM64 unit tests under qemu: $qemuTests"
qemu-aarch64 "$root/build-arch-aarch64/tests/perpdot-tests" --gtest_filter="$qemuTests" --gtest_brief=1 || failed=1
echo "== i386 unit tests ${i386Emulator[*]:+under qemu: $qemuTests}"
"${i386Emulator[@]}" "$root/build-arch-i386/tests/perpdot-tests" "${i386Tests[@]}" --gtest_brief=1 || failed=1
exit $failed
