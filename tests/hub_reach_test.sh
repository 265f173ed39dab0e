#!/bin/sh
# World::Impl, the hub, is opened only where the World is built, stepped, saved, or where its body,
# shape and joint calls are defined: exactly the files listed below include
# core/world/world_impl.hpp, and no header does. Every other file reads the world through the
# parts it names or a view of them (src/core/README.md).
# Usage: hub_reach_test.sh REPOSITORY_ROOT
set -u
root=$1
cd "$root/src" || exit 1
allowed="./core/bodies/body.cpp
./core/bodies/body_runtime.cpp
./core/joints/joint.cpp
./core/shapes/shape.cpp
./core/shapes/shape_runtime.cpp
./core/snapshot/snapshot.cpp
./core/world/step.cpp
./core/world/world.cpp"
includers=$(grep -rl '#include "core/world/world_impl.hpp"' . | sort)
count=$(echo "$includers" | grep -c .)
failed=0
for f in $includers; do
    if ! echo "$allowed" | grep -qx "$f"; then
        echo "hub reach: $f includes world_impl.hpp; take the parts it reads, or a view of them"
        failed=1
    fi
done
if [ "$count" -gt 8 ]; then
    echo "hub reach: $count files include world_impl.hpp, at most 8"
    failed=1
fi
[ $failed = 0 ] && echo "hub reach: $count files include world_impl.hpp (at most 8, no header among them)"
exit $failed
