// The broadphase re-fits proxies ahead, at poses predicted from the bodies' velocities, while the
// step is solved; finalizeBodies then re-fits whatever ended outside its fat AABB, and skips the
// check for bodies that strayed less from their predicted pose than their boxes had room
// (refit_ahead.cpp). If either went wrong, a shape would stick out of its fat AABB and the tree
// would miss it: a shape's own corner, queried as a point, must find the shape after every step.
#include <gtest/gtest.h>

#include <string>

#include "perpdot/scene.hpp"
#include "perpdot/world.hpp"

namespace perpdot {
namespace {

// Shapes of moving bodies (one child each) whose corner the tree misses.
int shapesOutsideTheirFatBoxes(const World& world) {
    int outside = 0;
    for (BodyId body : world.bodies()) {
        if (world.bodyType(body) == BodyType::Static) continue;
        for (ShapeId shape : world.shapes(body)) {
            if (world.shapeType(shape) == ShapeType::Chain) continue;
            const AABB box = world.aabb(shape);
            for (const Vec2 corner : {box.lower, box.upper, Vec2{box.lower.x, box.upper.y}, Vec2{box.upper.x, box.lower.y}}) {
                bool found = false;
                for (ShapeId hit : world.overlapAABB({corner, corner})) found = found || hit == shape;
                outside += found ? 0 : 1;
            }
        }
    }
    return outside;
}

struct Case {
    const char* scene;
    int steps;
};

// Falling, tumbling, bouncing, hinged and fast bodies: predictions that hold and ones a collision
// or a joint overturns.
TEST(RefitAhead, EveryShapeStaysInsideItsFatBox) {
    for (const Case c : {Case{"rain", 240}, Case{"tumbler", 240}, Case{"ragdoll", 180}, Case{"bullet_wall", 60},
                         Case{"car", 150}, Case{"dominoes", 200}, Case{"newtons_cradle", 200}, Case{"chain", 200}}) {
        for (int workers : {1, 2}) {
            SceneWorld built = buildWorld(findScene(c.scene), workers);
            for (int step = 0; step < c.steps; ++step) {
                built.step();
                ASSERT_EQ(shapesOutsideTheirFatBoxes(built.world), 0)
                    << c.scene << " after step " << step + 1 << " on " << workers << " workers";
            }
        }
    }
}

}  // namespace
}  // namespace perpdot
