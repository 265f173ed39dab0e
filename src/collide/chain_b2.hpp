// A chain in Box2D 2.4 terms, for the collide adapter and the cross-check's b2World: Box2D's
// one-sided edges collide on the right of v1→v2 (solid left), so a perpdot chain becomes the
// vertex order that puts its solid side on the left, and an open chain its ghost vertices.
#pragma once

#include <vector>

#include "perpdot/math.hpp"
#include "perpdot/shapes.hpp"

namespace perpdot::collide {

// The chain's vertices in Box2D's order and, for an open chain, its ghost vertices (given, or the
// end segments continued straight on). The collision system and the cross-check both build
// their edges from it.
struct ChainPath {
    std::vector<Vec2> vertices;
    Vec2 prev, next;  // open chains: before vertices[0], after the last
};
ChainPath box2dChainPath(const Chain& chain);

}  // namespace perpdot::collide
