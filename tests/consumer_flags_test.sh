#!/bin/sh
# The same game source (tests/consumer_flags/game.cpp) built with different flags prints one
# state_hash: the public headers keep a world's bits independent of the consumer's flags.
# Usage: consumer_flags_test.sh REFERENCE_EXE OTHER_EXE...
set -eu
reference=$("$1")
case $reference in state_hash=*) ;; *) echo "consumer_flags: $1 printed '$reference'" >&2; exit 1 ;; esac
echo "$1: $reference"
shift
for exe in "$@"; do
    got=$("$exe")
    echo "$exe: $got"
    [ "$got" = "$reference" ] || { echo "consumer_flags: $exe differs from the project's flags" >&2; exit 1; }
done
