// World::shiftOrigin (b2World::ShiftOrigin) over the parts that store world coordinates.
#pragma once

#include "core/bodies/body_store.hpp"
#include "core/contacts/contact_cache.hpp"
#include "core/joints/joint_store.hpp"
#include "core/shapes/broadphase.hpp"

namespace perpdot {

// Re-expresses bodies, contact points, pulley grounds and the broadphase about `newOrigin`.
void shiftOrigin(Pool<Body>& bodies, ContactCache& cache, JointStore& joints, Broadphase& broadphase, Vec2 newOrigin);

}  // namespace perpdot
