// A perpdot polygon as Box2D 2.4 geometry, for the collide adapter and the cross-check's b2World.
// Only collision.cpp and the cross-check include this header (it has Box2D types).
#pragma once

#include <box2d/b2_polygon_shape.h>

#include "perpdot/shapes.hpp"

namespace perpdot::collide {

// The validated convex polygon as it is (vertices, outward normals, centroid), never re-hulled;
// m_radius is Box2D's skin plus the polygon's rounding.
b2PolygonShape polygonToB2(const Polygon& polygon);

}  // namespace perpdot::collide
