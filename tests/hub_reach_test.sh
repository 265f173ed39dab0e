#!/bin/sh
# World::Impl, the hub, reaches no further than it does today: at most `max` files include
# core/world/world_impl.hpp, and the joint type files, the revolute trees, the snapshot's field
# lists and manifold reuse are not among them (src/core/README.md). Lower `max` when a file stops
# including it; never raise it.
# Usage: hub_reach_test.sh REPOSITORY_ROOT
set -u
root=$1
max=17
cd "$root/src" || exit 1
includers=$(grep -rl '#include "core/world/world_impl.hpp"' . | sort)
count=$(echo "$includers" | grep -c .)
failed=0
if [ "$count" -gt "$max" ]; then
    echo "hub reach: $count files include world_impl.hpp, at most $max:"
    echo "$includers"
    failed=1
fi
for f in core/joints/joint_tree.cpp core/joints/joint_distance.cpp core/joints/joint_gear.cpp core/joints/joint_mouse.cpp \
         core/joints/joint_filter.cpp core/joints/joint_motor.cpp core/joints/joint_prismatic.cpp core/joints/joint_pulley.cpp \
         core/joints/joint_revolute.cpp core/joints/joint_weld.cpp core/joints/joint_wheel.cpp \
         core/snapshot/snapshot_fields.hpp core/contacts/manifold_reuse.hpp; do
    if echo "$includers" | grep -qx "./$f"; then
        echo "hub reach: $f includes world_impl.hpp"
        failed=1
    fi
done
[ $failed = 0 ] && echo "hub reach: $count files include world_impl.hpp (at most $max); the joint type files, joint_tree.cpp, snapshot_fields.hpp and manifold_reuse.hpp do not"
exit $failed
