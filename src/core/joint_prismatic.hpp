// What the gear joint (joint_gear.cpp) reads of a prismatic joint.
#pragma once

#include "core/joint_store.hpp"

namespace perpdot {

// The prismatic joint's axis in body A's frame.
Vec2 prismaticLocalAxis(const Joint& prismatic);

}  // namespace perpdot
