#!/usr/bin/env bash
# Box2D 2.4.1 built so that its collision code computes the same bits on every CPU: Debian's own
# source package (`apt-get source box2d`, with Debian's patches), compiled by its own CMake as
# Debian does (-O2, no NDEBUG) plus -ffp-contract=off, into a static library. Debian's arm64
# libbox2d.so is compiled with the default -ffp-contract=fast and holds fused multiply-adds, which
# round once where x86-64 rounds twice; i386 adds -msse2 -mfpmath=sse (cmake/toolchains).
#
#   third_party/box2d-deterministic.sh native|aarch64|i386 [OUT_DIR]
#
# Installs into OUT_DIR/<target> (default: build-box2d/<target> in the repository) and prints that
# prefix, for `cmake -DPERPDOT_BOX2D_PREFIX=<prefix>`. A prefix already built from the same source
# version, compiler and flags is reused. Needs deb-src entries and dpkg-dev (third_party/install-deps.sh).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
target="${1:?usage: box2d-deterministic.sh native|aarch64|i386 [OUT_DIR]}"
out="$(mkdir -p "${2:-$root/build-box2d}" && cd "${2:-$root/build-box2d}" && pwd)"
flags="-O2 -ffp-contract=off"
case "$target" in
    native) toolchain=(); cxx="${CXX:-c++}" ;;
    aarch64) toolchain=(-DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/aarch64-linux-gnu.cmake"); cxx=aarch64-linux-gnu-g++ ;;
    i386) toolchain=(-DCMAKE_TOOLCHAIN_FILE="$root/cmake/toolchains/i686-linux-gnu.cmake"); cxx=i686-linux-gnu-g++
          flags+=" -msse2 -mfpmath=sse" ;;  # CMAKE_CXX_FLAGS replaces the toolchain's
    *) echo "box2d-deterministic.sh: unknown target '$target' (native, aarch64 or i386)" >&2; exit 2 ;;
esac
prefix="$out/$target"

# The source: Debian's box2d source package, unpacked once and shared by every target.
src="$out/src"
if [[ ! -f "$src/box2d-2.4.1/src/collision/b2_collide_polygon.cpp" ]]; then
    rm -rf "$src" && mkdir -p "$src"
    (cd "$src" && apt-get source box2d >&2)
fi
version="$(sed -n '1s/^box2d (\([^)]*\)).*/\1/p' "$src/box2d-2.4.1/debian/changelog")"
[[ "$version" == 2.4.1-* ]] || { echo "box2d-deterministic.sh: expected Debian's box2d 2.4.1, got '$version'" >&2; exit 1; }

stamp="box2d $version; $("$cxx" --version | head -n1); $flags"
if [[ -f "$prefix/lib/libbox2d.a" && "$(cat "$prefix/stamp" 2>/dev/null)" == "$stamp" ]]; then
    echo "$prefix"
    exit 0
fi
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
rm -rf "$prefix" "$out/build-$target"
cmake -S "$src/box2d-2.4.1" -B "$out/build-$target" "${toolchain[@]}" "${launcher[@]}" \
    -DCMAKE_BUILD_TYPE= -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
    -DBUILD_SHARED_LIBS=OFF -DBOX2D_BUILD_UNIT_TESTS=OFF -DBOX2D_BUILD_TESTBED=OFF -DBOX2D_BUILD_DOCS=OFF \
    -DCMAKE_INSTALL_PREFIX="$prefix" -DCMAKE_INSTALL_LIBDIR=lib >&2
cmake --build "$out/build-$target" -j"${PERPDOT_JOBS:-2}" >&2
cmake --install "$out/build-$target" >&2
echo "$stamp" >"$prefix/stamp"
echo "$prefix"
