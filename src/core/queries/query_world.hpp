// What the world's queries read (queries.cpp), and the explosion (explosion.cpp) and the character
// mover (mover.cpp) built on them: the broadphase tree, the shapes, the bodies' poses, the contacts
// and the identity their handles carry. They only read: what they push, they push through World's
// calls (applyLinearImpulse).
#pragma once

#include "collide/collision.hpp"
#include "core/bodies/body_store.hpp"
#include "core/contacts/contact_cache.hpp"
#include "core/shapes/shape_store.hpp"
#include "core/world/handle_check.hpp"

namespace perpdot {

struct QueryWorld {
    const collide::CollisionSystem& collision;
    const ShapeStore& shapes;
    const Pool<Body>& bodies;
    const ContactCache& contactCache;
    const WorldIdentity& identity;
    bool locked;  // inside step(): explode and moveMover refuse to run

    ShapeId shapeId(int shape) const { return handleAt<ShapeId>(shapes, shape, identity); }
    BodyId bodyId(int body) const { return handleAt<BodyId>(bodies, body, identity); }
};

QueryWorld queryWorld(const World::Impl& world);  // world.cpp

}  // namespace perpdot
