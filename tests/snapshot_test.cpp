// Snapshots: restore + N steps equals N steps, bit for bit (compared through the snapshot bytes
// themselves, which cover bodies, shapes, proxies and the contact cache with its impulses), and
// corrupt or truncated bytes are refused with perpdot::Error, leaving the world untouched.
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"
#include "perpdot/world.hpp"

namespace perpdot {
namespace {

using Bytes = std::vector<uint8_t>;

// Steps the scene `warmup` steps, snapshots, then continues `more` steps both in the original and
// in a fresh World restored from the snapshot; both must end in identical bytes.
void expectBitExactContinuation(const std::string& sceneName, int warmup, int more) {
    SceneWorld original = buildWorld(findScene(sceneName));
    for (int i = 0; i < warmup; ++i) original.step();
    const Bytes saved = original.world.snapshot();

    World restored;
    restored.restore(saved);
    EXPECT_EQ(restored.snapshot(), saved) << sceneName << ": restore then snapshot changes the bytes";
    for (int i = 0; i < more; ++i) {
        original.step();  // the actions of these scenes end at step 0, so plain steps suffice below
        restored.step(original.scene.timestep);
    }
    EXPECT_EQ(stateHash(restored), stateHash(original.world)) << sceneName;
    EXPECT_EQ(restored.snapshot(), original.world.snapshot()) << sceneName;
}

TEST(Snapshot, RestoreThenStepEqualsStepBitForBit) {
    expectBitExactContinuation("pyramid", 100, 200);          // many warm-started contacts
    expectBitExactContinuation("vertical_stack", 400, 100);   // asleep: island rings
    expectBitExactContinuation("rain", 90, 150);              // new pairs every step, circles and polygons
    expectBitExactContinuation("tumbler", 60, 120);           // kinematic body
    expectBitExactContinuation("rolling_disc", 30, 60);
    expectBitExactContinuation("card_house", 50, 100);
    expectBitExactContinuation("bullet_wall", 2, 30);         // continuous collision
    expectBitExactContinuation("conveyor", 60, 60);           // tangent speed
}

TEST(Snapshot, JointsAndTheirWarmStartsRestoreBitForBit) {
    for (const char* scene : {"chain", "suspension_bridge", "ragdoll", "car", "windmill", "prismatic_slider", "pendulum"})
        expectBitExactContinuation(scene, 45, 90);
}

// Destroying and creating after a restore: free lists, generations and the order new contacts are
// made in must not depend on the rebuilt broadphase tree.
TEST(Snapshot, CreationAndDestructionAfterRestoreMatch) {
    SceneWorld original = buildWorld(findScene("pyramid"));
    for (int i = 0; i < 60; ++i) original.step();
    World& a = original.world;
    a.destroyBody(original.bodies[5]);
    a.destroyBody(original.bodies[40]);  // leave holes in the pools
    World b;
    b.restore(a.snapshot());
    const float h = original.scene.timestep;
    for (World* w : {&a, &b}) {
        for (int i = 0; i < 50; ++i) w->step(h);
        w->destroyBody(original.bodies[100]);
        const BodyId ball = w->createBody({.type = BodyType::Dynamic, .position = {0.3f, 25.0f}});
        w->createShape(ball, {}, Circle{{0, 0}, 0.4f});
        for (int i = 0; i < 100; ++i) w->step(h);
    }
    EXPECT_EQ(stateHash(a), stateHash(b));
    EXPECT_EQ(a.snapshot(), b.snapshot());
    EXPECT_FALSE(b.isValid(original.bodies[5]));
    EXPECT_TRUE(b.isValid(original.bodies[6]));
}

// A world that has restored reads the next snapshot into the slots of the state it replaced
// (their shape and proxy lists' memory): nothing of that state may leak into the new one, whether
// the next snapshot has more slots or fewer, other shapes (a chain's many proxies) or the same.
TEST(Snapshot, RestoringAgainAndAgainLeavesNothingOfTheReplacedState) {
    auto stepped = [](const char* scene, int steps) {
        SceneWorld built = buildWorld(findScene(scene));
        for (int i = 0; i < steps; ++i) built.step();
        return built.world.snapshot();
    };
    const Bytes pyramid = stepped("pyramid", 60), rain = stepped("rain", 90);
    World cup;  // a chain: one shape of many children, each its proxy
    cup.createShape(cup.createBody({}), {}, Chain{{{-4, 4}, {-4, 0}, {0, -1}, {4, 0}, {4, 4}}, false, ChainSide::Left});
    for (int i = 0; i < 5; ++i)
        cup.createShape(cup.createBody({.type = BodyType::Dynamic, .position = {-2.0f + static_cast<float>(i), 3}}), {}, Circle{{0, 0}, 0.3f});
    for (int i = 0; i < 40; ++i) cup.step(1.0f / 60.0f);
    const Bytes terrain = cup.snapshot();
    World w;
    for (const Bytes* saved : {&pyramid, &terrain, &rain, &pyramid, &rain, &terrain, &terrain, &pyramid}) {
        w.restore(*saved);
        EXPECT_EQ(w.snapshot(), *saved);
    }
    World fresh;
    fresh.restore(pyramid);
    for (int i = 0; i < 60; ++i) {
        w.step(1.0f / 60.0f);
        fresh.step(1.0f / 60.0f);
    }
    EXPECT_EQ(stateHash(w), stateHash(fresh));
}

TEST(Snapshot, RestoreReplacesTheWorldAndKeepsIdsValid) {
    SceneWorld built = buildWorld(findScene("single_box"));
    for (int i = 0; i < 30; ++i) built.step();
    const Bytes saved = built.world.snapshot();
    World other({.gravity = {0, 5}});
    other.createBody({.type = BodyType::Dynamic, .position = {7, 7}});
    other.restore(saved);
    EXPECT_EQ(other.bodyCount(), built.world.bodyCount());
    EXPECT_EQ(other.settings().gravity, built.world.settings().gravity);
    for (BodyId id : built.bodies) EXPECT_EQ(other.position(id), built.world.position(id));
}

TEST(Snapshot, TruncatedSnapshotsAreRefusedAndLeaveTheWorldUnchanged) {
    SceneWorld built = buildWorld(findScene("bouncing_balls"));
    for (int i = 0; i < 40; ++i) built.step();
    const Bytes saved = built.world.snapshot();
    World target;
    target.restore(saved);
    const uint64_t before = stateHash(target);
    for (size_t size = 0; size < saved.size(); ++size) {
        try {
            target.restore(std::span(saved.data(), size));
            ADD_FAILURE() << "a snapshot cut to " << size << " of " << saved.size() << " bytes was accepted";
        } catch (const Error& e) {
            EXPECT_EQ(std::string(e.what()).rfind("snapshot: ", 0), 0u) << e.what();
        }
    }
    Bytes longer = saved;
    longer.push_back(0);
    EXPECT_THROW(target.restore(longer), Error);
    EXPECT_EQ(stateHash(target), before);
    EXPECT_EQ(target.snapshot(), saved);
}

std::string restoreError(const Bytes& bytes) {
    World world;
    try {
        world.restore(bytes);
    } catch (const Error& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(Snapshot, CorruptHeadersAreRefusedWithAClearMessage) {
    const Bytes saved = buildWorld(findScene("single_box")).world.snapshot();
    Bytes badMagic = saved;
    badMagic[0] ^= 0xFF;
    EXPECT_NE(restoreError(badMagic).find("not a perpdot snapshot"), std::string::npos);
    Bytes badVersion = saved;
    badVersion[8] += 1;
    EXPECT_NE(restoreError(badVersion).find("format version " + std::to_string(badVersion[8]) + " is not supported"),
              std::string::npos);
    EXPECT_NE(restoreError({}).find("truncated"), std::string::npos);
}

// Every single-byte corruption of a small snapshot either loads (then the world is consistent:
// it steps and re-snapshots to the corrupted bytes) or is refused with Error — under the sanitizer
// build this is the cheap deterministic sibling of the fuzzer.
// Every single-byte corruption is refused or loads, steps and saves back, in a fresh world. A
// rollback restores into a world that already holds the snapshot's shapes, and restore then skips
// re-checking a polygon equal to the one held in its slot and keeps a broadphase that already is
// the snapshot's: such a world must refuse exactly what a fresh one refuses, and load the same bytes.
TEST(Snapshot, SingleByteCorruptionsNeverCrash) {
    SceneWorld built = buildWorld(findScene("vertical_stack"));
    for (int i = 0; i < 30; ++i) built.step();
    const Bytes saved = built.world.snapshot();
    World holding;
    holding.restore(saved);
    int refused = 0;
    for (size_t i = 0; i < saved.size(); ++i) {
        for (uint8_t flip : {uint8_t{0x01}, uint8_t{0x80}, uint8_t{0xFF}}) {
            Bytes bad = saved;
            bad[i] ^= flip;
            World world;
            bool freshRefused = false, holdingRefused = false;
            try {
                world.restore(bad);
            } catch (const Error&) {
                freshRefused = true;
            }
            try {
                holding.restore(bad);
            } catch (const Error&) {
                holdingRefused = true;
            }
            ASSERT_EQ(holdingRefused, freshRefused) << "byte " << i;
            if (freshRefused) {
                ++refused;
                continue;
            }
            EXPECT_EQ(holding.snapshot(), bad) << "byte " << i;
            holding.restore(saved);  // the held shapes are the original ones again
            EXPECT_EQ(world.snapshot(), bad) << "byte " << i;
            for (int k = 0; k < 3; ++k) world.step(1.0f / 60.0f);
        }
    }
    EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace perpdot
