#!/bin/sh
# What builds or steps a world calls no C library transcendental function: their last bits differ
# between C libraries and CPUs. perpdot::sinCos, atan2 and exp (include/perpdot/portable_math.hpp,
# called unqualified inside namespace perpdot) are used instead; sqrt, correctly rounded by IEEE 754,
# may stay. Comments are left out of the search.
# Usage: no_libm_test.sh SOURCE_DIR
set -eu
cd "$1"
libm='(std::|::|[^A-Za-z0-9_:.>])(sinf?|cosf?|tanf?|asinf?|acosf?|atanf?|sinhf?|coshf?|tanhf?|exp2f?|expm1f?|logf?|log2f?|log10f?|log1pf?|powf?|hypotf?|cbrtf?|atan2f|expf) *\(|std::(atan2|exp) *\('
found=$(grep -rn '' include/perpdot src/core src/collide src/scene | sed 's#//.*##' | grep -E "$libm" || true)
if [ -n "$found" ]; then
    echo "no_libm: C library maths where a world is built or stepped:" >&2
    echo "$found" >&2
    exit 1
fi
echo "no_libm: include/perpdot, src/core, src/collide and src/scene call no C library transcendental"
