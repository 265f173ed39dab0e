#!/bin/sh
# The configure's Box2D check (cmake/box2d_determinism.cmake) both ways: it accepts the Box2D this
# build links, refuses an object whose multiply-add the compiler fused (naming the function and
# the opt-out option), accepts it with PERPDOT_ALLOW_NONDETERMINISTIC_BOX2D=ON, and on 32-bit x86
# refuses x87 arithmetic too.
#   box2d_determinism_test.sh CMAKE SOURCE_DIR CXX OBJDUMP X87(ON|OFF) LINKED_BOX2D
set -eu
cmake="$1" source="$2" cxx="$3" objdump="$4" x87="$5" linked="$6"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
check() {  # library [extra cmake -D...]: the check's exit status; its output in $work/out
    lib="$1"; shift
    "$cmake" -DLIBRARY="$lib" -DOBJDUMP="$objdump" -DX87="$x87" "$@" -P "$source/cmake/box2d_determinism.cmake" >"$work/out" 2>&1
}
fail() { echo "FAIL: $*"; cat "$work/out"; exit 1; }

check "$linked" || fail "the linked Box2D $linked is refused"

printf 'float multiplyAdd(float a, float b, float c) { return a * b + c; }\n' >"$work/fma.cpp"
fmaFlag=""
sse=""
[ "$x87" = ON ] && sse="-msse2 -mfpmath=sse"  # as the build compiles on 32-bit x86
"$cxx" -mfma -c -x c++ /dev/null -o "$work/probe.o" 2>/dev/null && fmaFlag="-mfma"  # x86: FMA3
"$cxx" -O2 -ffp-contract=fast $sse $fmaFlag -c "$work/fma.cpp" -o "$work/fma.o"
if check "$work/fma.o"; then fail "an object with a fused multiply-add passes"; fi
grep -q "PERPDOT_ALLOW_NONDETERMINISTIC_BOX2D=ON" "$work/out" || fail "the refusal does not name the opt-out option"
grep -q "[0-9] in multiplyAdd(float, float, float)" "$work/out" || fail "the refusal does not name the function"
check "$work/fma.o" -DPERPDOT_ALLOW_NONDETERMINISTIC_BOX2D=ON || fail "the opt-out does not let it pass"

"$cxx" -O2 -ffp-contract=off $sse -c "$work/fma.cpp" -o "$work/separate.o"
check "$work/separate.o" || fail "a multiply and an add compiled apart are refused"

if [ "$x87" = ON ]; then
    "$cxx" -O2 -ffp-contract=off -mfpmath=387 -c "$work/fma.cpp" -o "$work/x87.o"
    if check "$work/x87.o"; then fail "x87 arithmetic passes on 32-bit x86"; fi
fi
echo "box2d determinism check: accepts $linked, refuses a fused multiply-add (x87 checked: $x87)"
