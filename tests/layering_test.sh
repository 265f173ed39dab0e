#!/bin/sh
# The layers' include fences (cmake/perpdot_layer.cmake) hold: with a layer's include directories,
# the preprocessor finds (__has_include) its own and lower layers' headers, and none of a layer above.
# Usage: layering_test.sh CXX "CORE_INCLUDE_DIRS" "SCENE_INCLUDE_DIRS" "CROSSCHECK_INCLUDE_DIRS"
# (each a :-separated list).
set -u
cxx=$1 core=$2 scene=$3 crosscheck=$4
failed=0
check() {  # expected(found|missing) layer dirs header
    flags=$(echo "$3" | tr ':' '\n' | sed 's/^/-I/' | tr '\n' ' ')
    # shellcheck disable=SC2086  # flags are words
    if printf '#if !__has_include("%s")\n#error\n#endif\n' "$4" | $cxx -std=c++20 -E $flags -x c++ - -o /dev/null 2>/dev/null
    then got=found; else got=missing; fi
    if [ "$got" != "$1" ]; then
        echo "layering: $4 is $got from $2, expected $1"
        failed=1
    fi
}
for h in perpdot/scene.hpp perpdot/feature_scenes.hpp perpdot/crosscheck.hpp scene/build_world.hpp crosscheck/stepper.hpp; do
    check missing core "$core" $h
done
for h in perpdot/perpdot.hpp core/step_context.hpp collide/pair_set.hpp; do
    check found core "$core" $h
done
for h in perpdot/crosscheck.hpp crosscheck/stepper.hpp; do
    check missing scene "$scene" $h
done
for h in perpdot/scene.hpp perpdot/feature_scenes.hpp perpdot/world.hpp scene/scene_script.hpp; do
    check found scene "$scene" $h
done
for h in perpdot/crosscheck.hpp perpdot/scene.hpp crosscheck/stepper.hpp scene/build_world.hpp; do
    check found crosscheck "$crosscheck" $h
done
[ $failed = 0 ] && echo "layering: core sees neither scene nor crosscheck headers, scene does not see crosscheck's"
exit $failed
