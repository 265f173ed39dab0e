// A hanging net of discs linked by revolute joints, pinned at the middle of its top row (the
// joint_grid benchmark, smaller). Each body sits in up to four joints, so the rows couple in a 2D
// lattice: a row formulation that is stable along a chain can still pump energy into the net.
// Gravity and joints do no net work, so the mechanical energy may only fall (soft rows dissipate).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "joint_helpers.hpp"

namespace perpdot {
namespace {

using namespace joint_test;

TEST(JointGrid, HangingNetNeverGainsEnergy) {
    World world;
    const int n = 30;
    std::vector<BodyId> grid(n * n);
    auto at = [&](int k, int i) -> BodyId& { return grid[k * n + i]; };
    for (int k = 0; k < n; ++k) {
        for (int i = 0; i < n; ++i) {
            const Vec2 p{static_cast<float>(k), -static_cast<float>(i)};
            const bool pinned = i == 0 && k >= n / 2 - 3 && k <= n / 2 + 3;
            at(k, i) = pinned ? staticBody(world, p) : disc(world, p, 0.4f);
            if (i > 0) world.createJoint(hinge(world, at(k, i - 1), at(k, i), p + Vec2{0.0f, 0.5f}));
            if (k > 0) world.createJoint(hinge(world, at(k - 1, i), at(k, i), p - Vec2{0.5f, 0.0f}));
        }
    }
    auto total = [&] {
        float e = 0.0f;
        for (BodyId b : grid)
            if (world.mass(b) > 0.0f) e += energy(world, b);
        return e;
    };
    const float start = total();
    for (int step = 0; step < 300; ++step) {
        world.step(1.0f / 60.0f);
        ASSERT_LE(total(), start + 1e-3f * std::abs(start)) << "energy gained by step " << step;
    }
}

}  // namespace
}  // namespace perpdot
