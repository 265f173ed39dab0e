// Capsules in Box2D 2.4 terms: a 2-vertex b2PolygonShape whose m_radius is the capsule radius.
// Box2D 2.4's polygon routines take such a polygon (b2Distance, b2TimeOfImpact, the AABB and the
// polygon/circle manifold are exact for it), but three places need help, done here:
//  - b2CollidePolygons and b2CollideEdgeAndPolygon test face normals only; a segment has no end
//    faces, so near a cap they can report a contact along a side normal (or none at all after the
//    side-plane clip). capsuleManifold() re-checks with the core distance.
//  - b2PolygonShape::RayCast and TestPoint ignore m_radius: rayCastCapsule() and
//    capsuleContains() measure against the rounded surface.
// Only collision.cpp and the cross-check include this header (it has Box2D types).
#pragma once

#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include "perpdot/shapes.hpp"

namespace perpdot::collide {

// The capsule as Box2D 2.4 geometry (vertices center1, center2; normals ±perp; m_radius = radius).
b2PolygonShape capsuleToB2(const Capsule& capsule);
// Whether a Box2D shape is a capsule (a 2-vertex polygon).
bool isCapsule(const b2Shape& shape);

// Replaces `manifold` (from b2CollidePolygons or b2CollideEdgeAndPolygon for a pair with a
// capsule) with a one-point manifold along the closest points of the cores when the two differ:
// cores farther apart than the radii → no points; closest features not face-to-face (their
// direction is off the manifold normal by more than ~5°) → one point at the closest features.
// Face-to-face contacts keep Box2D's clipped two-point manifold.
void capsuleManifold(b2Manifold& manifold, const b2Shape& a, const b2Transform& xfA, const b2Shape& b, const b2Transform& xfB);

// The ray against the rounded capsule: the two cap circles and the two side segments.
bool rayCastCapsule(const b2PolygonShape& capsule, const b2Transform& xf, const b2RayCastInput& input, b2RayCastOutput& output);
// Whether the point lies within radius of the capsule's core segment.
bool capsuleContains(const b2PolygonShape& capsule, const b2Transform& xf, const b2Vec2& point);

}  // namespace perpdot::collide
