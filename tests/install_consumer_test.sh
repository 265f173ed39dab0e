#!/bin/sh
# Install the build tree into a temporary prefix, then configure, build and run
# examples/quickstart against it with find_package(perpdot), as an outside project would.
# Usage: install_consumer_test.sh CMAKE BUILD_DIR SOURCE_DIR
set -eu
cmake=$1 build=$2 source=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$cmake" --install "$build" --prefix "$work/prefix" >/dev/null
"$cmake" -S "$source/examples/quickstart" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release >/dev/null
"$cmake" --build "$work/build" -j2 >/dev/null
"$work/build/quickstart"
