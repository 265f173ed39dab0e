// The proxies a CollisionSystem's tree query reports for a probe box, and those whose fat AABBs
// overlap it by brute force: the two sets a correct tree makes equal.
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "collide/collision.hpp"

namespace perpdot::collide::test {

inline std::pair<std::set<int>, std::set<int>> foundAndExpected(const CollisionSystem& collision, const std::vector<int>& proxies,
                                                                const AABB& probe) {
    std::set<int> found, expected;
    collision.query(probe, [&](int proxy) {
        found.insert(proxy);
        return true;
    });
    for (int proxy : proxies)
        if (overlaps(collision.fatAABB(proxy), probe)) expected.insert(proxy);
    return {found, expected};
}

}  // namespace perpdot::collide::test
