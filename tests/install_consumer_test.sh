#!/bin/sh
# An outside project (examples/quickstart) builds against perpdot and runs, the three ways a game
# consumes a C++ library:
#   1. find_package(perpdot) after `cmake --install` into a temporary prefix -- perpdot::core, and
#      perpdot::perpdot (all layers, as before the split) with the scene header;
#   2. pkg-config: the compiler alone with `pkg-config --cflags --libs perpdot`;
#   3. add_subdirectory of the source tree, with BUILD_SHARED_LIBS=ON: only the libraries are
#      configured (no tests, demos, CLI), no warning flag reaches the consumer's compile, and
#      libperpdot.so carries its SONAME.
# Usage: install_consumer_test.sh CMAKE BUILD_DIR SOURCE_DIR CXX [LAUNCHER]
# Works in BUILD_DIR/install_consumer (a fixed path, so a compiler launcher such as ccache can reuse
# the subproject's objects from one run to the next).
set -eu
cmake=$1 build=$2 source=$3 cxx=$4 launcher=${5:-}
work=$build/install_consumer
rm -rf "$work"
mkdir -p "$work"
fail() { echo "install_consumer: $*" >&2; exit 1; }
configure() {  # source build args...
    src=$1 dir=$2; shift 2
    "$cmake" -S "$src" -B "$dir" -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER="$cxx" \
        ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"} "$@" >"$dir.log" 2>&1 || { cat "$dir.log"; fail "configure $dir"; }
}

echo "== find_package"
"$cmake" --install "$build" --prefix "$work/prefix" >/dev/null
configure "$source/examples/quickstart" "$work/find_package" -DCMAKE_PREFIX_PATH="$work/prefix"
"$cmake" --build "$work/find_package" -j2 >/dev/null
"$work/find_package/quickstart"
mkdir -p "$work/compat_src"
cat >"$work/compat_src/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.25)
project(perpdot_compat LANGUAGES CXX)
find_package(perpdot REQUIRED)
add_executable(compat main.cpp)
target_link_libraries(compat PRIVATE perpdot::perpdot)
CMAKE
cat >"$work/compat_src/main.cpp" <<CPP
#include <perpdot/perpdot.hpp>
#include <perpdot/scene.hpp>
int main() { return perpdot::buildWorld(perpdot::findScene("single_box")).world.bodyCount() > 0 ? 0 : 1; }
CPP
configure "$work/compat_src" "$work/compat" -DCMAKE_PREFIX_PATH="$work/prefix"
"$cmake" --build "$work/compat" -j2 >/dev/null
"$work/compat/compat" || fail "perpdot::perpdot consumer"

echo "== pkg-config"
pc=$(find "$work/prefix" -name perpdot.pc)
[ -n "$pc" ] || fail "no perpdot.pc installed"
flags=$(PKG_CONFIG_PATH=$(dirname "$pc") pkg-config --cflags --libs perpdot)
echo "pkg-config --cflags --libs perpdot: $flags"
# shellcheck disable=SC2086  # the flags are words
$cxx -std=c++20 "$source/examples/quickstart/main.cpp" $flags -o "$work/quickstart_pkgconfig"
"$work/quickstart_pkgconfig"
# A game built with every warning as an error: designated initialisers that leave fields out
# (GCC's -Wmissing-field-initializers) and the public headers compile clean.
cat >"$work/wextra.cpp" <<'CPP'
#include <perpdot/perpdot.hpp>
int main() {
    perpdot::World world(perpdot::WorldDef{.gravity = {0.0f, -10.0f}});
    const perpdot::BodyId ground = world.createBody({.type = perpdot::BodyType::Static});
    world.createShape(ground, {.friction = 0.8f}, perpdot::Segment{.v1 = {-5, 0}, .v2 = {5, 0}});
    const perpdot::BodyId box = world.createBody({.type = perpdot::BodyType::Dynamic, .position = {0, 2}});
    world.createShape(box, {.density = 2.0f}, perpdot::makeBox(0.5f, 0.5f));
    const perpdot::BodyId wheel = world.createBody({.type = perpdot::BodyType::Dynamic, .position = {2, 2}});
    world.createShape(wheel, {}, perpdot::Circle{.radius = 0.25f});
    world.createJoint(perpdot::RevoluteJointDef{.bodyA = box, .bodyB = wheel, .enableLimit = true});
    for (int i = 0; i < 120; ++i) world.step(1.0f / 60.0f);
    return world.position(box).y < 1.0f ? 0 : 1;
}
CPP
# shellcheck disable=SC2086  # the flags are words
$cxx -std=c++20 -Wall -Wextra -Werror "$work/wextra.cpp" $flags -o "$work/wextra" || fail "-Wall -Wextra -Werror consumer"
"$work/wextra" || fail "-Wextra consumer: the box did not fall to the ground"

echo "== add_subdirectory, BUILD_SHARED_LIBS=ON"
configure "$source/examples/quickstart" "$work/subdirectory" -DPERPDOT_SOURCE_DIR="$source" \
    -DBUILD_SHARED_LIBS=ON -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
for target in perpdot-tests perpdot-cli perpdot-demo perpdot-microbench perpdot-docs; do
    "$cmake" --build "$work/subdirectory" --target help | grep -q "\\.\\.\\. $target\$" && fail "the subproject defines $target"
done
"$cmake" --build "$work/subdirectory" --target quickstart -j2 >/dev/null
grep '"command"' "$work/subdirectory/compile_commands.json" | grep 'quickstart/main.cpp' | grep -q -e '-W' -e '-ffp-contract' &&
    fail "perpdot's warning flags leak into the consumer's compile"
lib=$(find "$work/subdirectory/perpdot" -maxdepth 1 -name 'libperpdot.so.*.*.*')
[ -n "$lib" ] || fail "no libperpdot.so.<version> in the subproject build"
soname=$(objdump -p "$lib" | awk '/SONAME/ {print $2}')
echo "$(basename "$lib"): SONAME $soname"
[ "$soname" = "libperpdot.so.$(basename "$lib" | cut -d. -f3-4)" ] || fail "SONAME $soname"
"$work/subdirectory/quickstart"
rm -rf "$work"  # kept on failure, to look at
