// A chain in Box2D 2.4 terms (chain_b2.hpp).
#include "collide/chain_b2.hpp"

#include <algorithm>
#include <cstddef>
#include <optional>

namespace perpdot::collide {

ChainPath box2dChainPath(const Chain& chain) {
    ChainPath path{chain.vertices, {}, {}};
    // Box2D's one-sided edges collide on the right of v1→v2 (solid left): a chain solid on the
    // right runs the other way, its ghosts swapped.
    const bool reversed = chain.solid == ChainSide::Right;
    if (reversed) std::reverse(path.vertices.begin(), path.vertices.end());
    const std::optional<Vec2>& prev = reversed ? chain.nextVertex : chain.prevVertex;
    const std::optional<Vec2>& next = reversed ? chain.prevVertex : chain.nextVertex;
    const std::vector<Vec2>& v = path.vertices;
    const size_t n = v.size();
    if (!chain.loop) {  // ghosts not given: the end segments continued straight on
        path.prev = prev ? *prev : v[0] + (v[0] - v[1]);
        path.next = next ? *next : v[n - 1] + (v[n - 1] - v[n - 2]);
    }
    return path;
}

}  // namespace perpdot::collide
