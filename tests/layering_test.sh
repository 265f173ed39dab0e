#!/bin/sh
# The layers' include fences (cmake/perpdot_layer.cmake) hold: with a layer's include directories,
# the preprocessor finds (__has_include) its own headers and what the layers below export, and
# none of a layer above nor a lower layer's private ones.
# Usage: layering_test.sh CXX "COLLIDE_DIRS" "SOLVER_DIRS" "CORE_DIRS" "SCENE_DIRS" "CROSSCHECK_DIRS"
# (each a :-separated list).
set -u
cxx=$1 collide=$2 solver=$3 core=$4 scene=$5 crosscheck=$6
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
# collide: the Box2D adapter and the SIMD lanes, below the engine: the math and shape headers only.
for h in perpdot/world.hpp perpdot/body.hpp core/world/world_impl.hpp core/solver/lanes.hpp perpdot/scene.hpp scene/build_world.hpp; do
    check missing collide "$collide" $h
done
for h in perpdot/math.hpp perpdot/shapes.hpp collide/collision.hpp simd/simd.hpp; do
    check found collide "$collide" $h
done
# solver: its own folder, collide's collision and SIMD headers, the engine's public headers and the
# core headers its view of the world (solver_world.hpp) is made of; not the hub, nor the rest of core.
for h in core/world/world_impl.hpp core/world/stages.hpp core/contacts/continuous.hpp core/joints/joint_store.hpp \
         core/shapes/shape_store.hpp collide/time_of_impact.hpp perpdot/scene.hpp scene/build_world.hpp; do
    check missing solver "$solver" $h
done
for h in core/solver/solver_world.hpp core/solver/avx2/contact_solver_avx2.cpp core/world/step_scratch.hpp \
         core/world/step_context.hpp core/contacts/contact_cache.hpp core/joints/joint.hpp core/bodies/integrate.hpp \
         core/threads/workers.hpp collide/collision.hpp simd/simd.hpp perpdot/world.hpp; do
    check found solver "$solver" $h
done
# core: the engine, with collide and solver as its parts.
for h in perpdot/scene.hpp perpdot/feature_scenes.hpp perpdot/crosscheck.hpp scene/build_world.hpp crosscheck/stepper.hpp; do
    check missing core "$core" $h
done
for h in perpdot/perpdot.hpp core/world/step_context.hpp core/solver/solver_world.hpp collide/pair_set.hpp simd/simd.hpp; do
    check found core "$core" $h
done
# scene: the engine through its public headers.
for h in perpdot/crosscheck.hpp crosscheck/stepper.hpp core/world/world_impl.hpp collide/collision.hpp; do
    check missing scene "$scene" $h
done
for h in perpdot/scene.hpp perpdot/feature_scenes.hpp perpdot/world.hpp scene/scene_script.hpp; do
    check found scene "$scene" $h
done
# crosscheck: the engine's public headers, scene's, and of collide only its Box2D shape adapters.
for h in core/world/world_impl.hpp collide/collision.hpp collide/pair_set.hpp simd/simd.hpp; do
    check missing crosscheck "$crosscheck" $h
done
for h in perpdot/crosscheck.hpp perpdot/scene.hpp crosscheck/stepper.hpp scene/build_world.hpp collide/polygon_b2.hpp collide/chain_b2.hpp; do
    check found crosscheck "$crosscheck" $h
done
[ $failed = 0 ] && echo "layering: collide sees only the math and shape headers; solver sees its view of the world, not the hub; core sees neither scene nor crosscheck; scene sees no engine internals; crosscheck sees of collide only its Box2D adapters"
exit $failed
