// The contact rows eight at a time (AVX2) and four at a time (SSE2) give the same world, bit for
// bit: a colour's constraints share no moving body, so the lane width only regroups them. The
// width is chosen when a world is made (chooseContactLanes: PERPDOT_CONTACT_LANES=4 asks for four).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "core/solver/contact_solver_wide.hpp"
#include "perpdot/feature_scenes.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"
#include "scene/build_world.hpp"

namespace perpdot {
namespace {

uint64_t hashWithLanes(const char* lanes, const std::string& sceneName, int steps, int workers) {
    ::setenv("PERPDOT_CONTACT_LANES", lanes, 1);
    Scene scene = findScene(sceneName);
    scene.steps = steps;
    SceneWorld built = buildWorldWithBehaviour(scene, workers);
    ::unsetenv("PERPDOT_CONTACT_LANES");
    for (int i = 0; i < steps; ++i) built.step();
    return stateHash(built.world);
}

TEST(ContactLanes, AskingForFourLanesGivesFour) {
    ::setenv("PERPDOT_CONTACT_LANES", "4", 1);
    EXPECT_EQ(chooseContactLanes(), 4);
    ::unsetenv("PERPDOT_CONTACT_LANES");
    EXPECT_EQ(chooseContactLanes(), contactLanes8Available() ? 8 : 4);
}

// Stacks, a card house (friction at its limit), restitution, rolling resistance and conveyors,
// rounded shapes, a churning broadphase, bullets, sleep; large_pyramid and smash have colours of
// hundreds of blocks and an overflow colour.
TEST(ContactLanes, EightLanesGiveTheSameWorldAsFour) {
    if (!contactLanes8Available()) GTEST_SKIP() << "this build or CPU has no AVX2 contact rows";
    struct Case {
        const char* scene;
        int steps;
    };
    for (const Case c : {Case{"pyramid", 200}, Case{"card_house", 200}, Case{"bouncing_balls", 200}, Case{"rolling_disc", 120},
                         Case{"tumbler", 150}, Case{"rain", 200}, Case{"bullet_wall", 40}, Case{"conveyor", 120},
                         Case{"large_pyramid", 20}, Case{"smash", 30}})
        for (int workers : {1, 2})
            EXPECT_EQ(hashWithLanes("8", c.scene, c.steps, workers), hashWithLanes("4", c.scene, c.steps, workers))
                << c.scene << " on " << workers << " workers";
}

}  // namespace
}  // namespace perpdot
