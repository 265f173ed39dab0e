#!/bin/sh
# perpdot's libraries hold no out-of-line copy of an inline function of include/perpdot/math.hpp:
# such a copy is a weak symbol, and when a game's object file defines the same symbol (compiled
# with the game's flags, say -ffast-math) the linker may keep the game's copy for the library's
# calls too. Inlined everywhere, the library's arithmetic is compiled with its own flags only.
# Usage: inline_math_test.sh MATH_HPP LIBRARY...
set -eu
header=$1
shift
# The header's function names: `constexpr T name(`, `inline T name(`, and its operators.
names=$(sed -nE 's/^ *(static )?(constexpr|inline) [^(]* ([A-Za-z_][A-Za-z0-9_]*|operator[^(]*)\(.*/\3/p' "$header" | sort -u)
[ -n "$names" ] || { echo "inline_math: no functions found in $header" >&2; exit 1; }
pattern=$(printf '%s\n' $names | sed 's/[][*+.^$\\-]/\\&/g' | paste -sd'|')
found=$(nm -C "$@" | grep -E ' [WVTt] ' | grep -E "perpdot::((Vec2|Rot|detail)::)?($pattern)\(" || true)
if [ -n "$found" ]; then
    echo "inline_math: out-of-line copies of math.hpp functions in the library:" >&2
    echo "$found" >&2
    exit 1
fi
echo "inline_math: none of $(printf '%s ' $names)has an out-of-line copy in $*"
