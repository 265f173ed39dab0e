// perpdot's vectors, poses and circles as Box2D 2.4 values: one conversion for the collide
// adapter, the cross-check's b2World and tests that compare with Box2D's own calls.
// Only code that may see Box2D types includes this header.
#pragma once

#include <box2d/b2_circle_shape.h>
#include <box2d/b2_math.h>

#include "perpdot/math.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot::collide {

inline b2Vec2 toB2(Vec2 v) { return {v.x, v.y}; }

inline b2Transform toB2(const Transform& xf) {
    b2Transform t;
    t.p = toB2(xf.p);
    t.q.c = xf.q.c;
    t.q.s = xf.q.s;
    return t;
}

inline b2CircleShape toB2(const Circle& circle) {
    b2CircleShape c;
    c.m_p = toB2(circle.center);
    c.m_radius = circle.radius;
    return c;
}

}  // namespace perpdot::collide
