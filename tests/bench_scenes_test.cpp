// The benchmark scenes of Box2D v3's suite (bench_tumbler, smash, ragdoll_rain, spinner, washer,
// compounds, junkyard), distance_net and motor_swarm: their counts, their JSON round trip
// (joint_rack's too), the scripts of ragdoll_rain and junkyard in both engines, a physical check of
// washer, compounds and junkyard, and the stability figures `perpdot bench` prints, on small cases
// whose answers are known. No timings are checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "crosscheck/stability.hpp"
#include "crosscheck/stepper.hpp"
#include "perpdot/error.hpp"
#include "perpdot/scene.hpp"
#include "scene/ragdoll_figure.hpp"
#include "scene/scene_script.hpp"

namespace perpdot {
namespace {

using crosscheck::BodySample;
using crosscheck::Engine;
using crosscheck::StabilityProbe;

int countType(const Scene& s, BodyType type) {
    return int(std::count_if(s.bodies.begin(), s.bodies.end(), [type](const SceneBody& b) { return b.type == type; }));
}

bool sleepOff(const Scene& s) {
    return std::all_of(s.bodies.begin(), s.bodies.end(),
                       [](const SceneBody& b) { return b.type == BodyType::Static || !b.allowSleep; });
}

TEST(BenchScenes, TumblerIsABoxTurnedByAMotorHolding2025Boxes) {
    const Scene s = findScene("bench_tumbler");
    EXPECT_EQ(s.steps, 750);
    EXPECT_FLOAT_EQ(s.timestep, 1.0f / 60.0f);
    EXPECT_EQ(s.bodies.size(), 2u + 45u * 45u);  // ground, container, boxes
    EXPECT_EQ(countType(s, BodyType::Dynamic), 1 + 2025);
    ASSERT_EQ(s.joints.size(), 1u);
    EXPECT_TRUE(s.joints[0].enableMotor);
    EXPECT_NEAR(s.joints[0].motorSpeed, 25.0f * pi / 180.0f, 1e-6f);
    EXPECT_EQ(s.bodies[1].name, "container");
    EXPECT_EQ(s.bodies[1].shapes.size(), 4u);
    EXPECT_FLOAT_EQ(s.bodies[2].shapes[0].halfExtents.x, 0.125f);
    EXPECT_TRUE(sleepOff(s));
}

TEST(BenchScenes, SmashIsAnEightMetreBoxIntoA120By80Block) {
    const Scene s = findScene("smash");
    EXPECT_EQ(s.steps, 300);
    EXPECT_EQ(s.gravity, (Vec2{0.0f, 0.0f}));
    EXPECT_EQ(s.bodies.size(), 1u + 120u * 80u);
    EXPECT_TRUE(s.joints.empty());
    const SceneBody& ram = s.bodies[0];
    EXPECT_EQ(ram.shapes[0].halfExtents, (Vec2{4.0f, 4.0f}));
    EXPECT_FLOAT_EQ(ram.shapes[0].density, 8.0f);
    EXPECT_EQ(ram.linearVelocity, (Vec2{40.0f, 0.0f}));
    EXPECT_EQ(s.bodies[1].shapes[0].halfExtents, (Vec2{0.2f, 0.2f}));
    EXPECT_TRUE(std::all_of(s.bodies.begin() + 1, s.bodies.end(), [](const SceneBody& b) { return !b.awake && b.allowSleep; }));
}

// The block sleeps until the ram's face (x = -16 m at 40 m/s) reaches its first column (29.8 m)
// after 45.8/40 s = 68.7 steps, and wakes from there.
TEST(BenchScenes, SmashBlockSleepsUntilTheRamArrives) {
    SceneWorld built = buildWorld(findScene("smash"));
    auto awakeBlocks = [&] {
        return std::count_if(built.bodies.begin() + 1, built.bodies.end(), [&](BodyId b) { return built.world.isAwake(b); });
    };
    for (int i = 0; i < 68; ++i) built.step();
    EXPECT_EQ(awakeBlocks(), 0);
    EXPECT_EQ(built.world.position(built.bodies[1]), findScene("smash").bodies[1].position);
    for (int i = 0; i < 4; ++i) built.step();
    EXPECT_GT(awakeBlocks(), 0);
}

TEST(BenchScenes, SpinnerIsAMotorisedBarIn6000ShapesInAChainLoop) {
    const Scene s = findScene("spinner");
    EXPECT_EQ(s.steps, 500);
    EXPECT_EQ(s.bodies.size(), 2u + 6000u);  // container (the loop), bar, shapes
    ASSERT_EQ(s.joints.size(), 1u);
    EXPECT_FLOAT_EQ(s.joints[0].motorSpeed, 5.0f);
    const SceneShape& loop = s.bodies[0].shapes[0];
    EXPECT_EQ(loop.kind, SceneShape::Kind::Chain);
    EXPECT_TRUE(loop.loop);
    for (const Vec2 v : loop.vertices) EXPECT_NEAR(length(v - Vec2{0.0f, 32.0f}), 40.0f, 1e-3f);
    int kinds[3] = {};
    for (size_t i = 2; i < s.bodies.size(); ++i) ++kinds[int(s.bodies[i].shapes[0].kind)];  // Circle, Box, Polygon
    EXPECT_EQ(kinds[0], 2000);
    EXPECT_EQ(kinds[1], 2000);
    EXPECT_EQ(kinds[2], 2000);
    EXPECT_TRUE(sleepOff(s));
}

TEST(BenchScenes, RagdollRainStartsWithFiveShelvesAndAScript) {
    const Scene s = findScene("ragdoll_rain");
    EXPECT_EQ(s.steps, 1000);
    ASSERT_EQ(s.bodies.size(), 1u);
    EXPECT_EQ(s.bodies[0].shapes.size(), 5u * 501u);
    EXPECT_NE(makeSceneScript("ragdoll_rain"), nullptr);
    EXPECT_EQ(makeSceneScript("pyramid"), nullptr);
}

TEST(BenchScenes, RagdollSceneUsesTheSharedFigure) {
    const Scene s = findScene("ragdoll");
    EXPECT_EQ(s.bodies.size(), 1u + ragdollBodyCount);
    EXPECT_EQ(s.joints.size(), size_t(ragdollJointCount));
    EXPECT_FLOAT_EQ(s.bodies[1].angularVelocity, 2.0f);
}

// 32 ropes of 16 rods and 12 blobs of 5 × 5 discs tied by 72 distance joints each: 9 blobs of
// springs with min and max lengths, 3 rigid.
TEST(BenchScenes, DistanceNetIsRopesOfRodsAndBlobsOfSprings) {
    const Scene s = findScene("distance_net");
    EXPECT_EQ(s.steps, 500);
    EXPECT_EQ(s.bodies.size(), 2u + 32u * 16u + 12u * 25u);  // ground, ceiling, beads, discs
    ASSERT_EQ(s.joints.size(), 32u * 16u + 12u * 72u);
    int springs = 0;
    for (const SceneJoint& j : s.joints) {
        EXPECT_EQ(j.type, JointType::Distance);
        if (j.hertz == 0.0f) continue;
        ++springs;
        ASSERT_TRUE(j.anchor && j.anchorB);
        const float rest = length(*j.anchorB - *j.anchor);
        EXPECT_FLOAT_EQ(j.minLength, 0.8f * rest);
        EXPECT_FLOAT_EQ(j.maxLength, 1.2f * rest);
    }
    EXPECT_EQ(springs, 9 * 72);
    EXPECT_TRUE(sleepOff(s));
}

// 400 boxes on motor joints from the ground, 100 carts each carrying a box on one.
TEST(BenchScenes, MotorSwarmIsBoxesAndCartsOnMotorJoints) {
    const Scene s = findScene("motor_swarm");
    EXPECT_EQ(s.steps, 500);
    EXPECT_EQ(s.bodies.size(), 1u + 400u + 2u * 100u);  // ground, boxes, carts and their loads
    ASSERT_EQ(s.joints.size(), 500u);
    for (const SceneJoint& j : s.joints) EXPECT_EQ(j.type, JointType::Motor);
    EXPECT_EQ(std::count_if(s.joints.begin(), s.joints.end(), [](const SceneJoint& j) { return j.bodyA == "ground"; }), 400);
    EXPECT_TRUE(sleepOff(s));
}

// Records every edit; the script under test never touches an engine.
class RecordingEditor final : public SceneEditor {
public:
    Group spawn(const Scene& fragment) override {
        bodies += int(fragment.bodies.size());
        joints += int(fragment.joints.size());
        alive.push_back(next);
        return next++;
    }
    void destroy(Group group) override {
        const auto it = std::find(alive.begin(), alive.end(), group);
        ASSERT_NE(it, alive.end()) << "group " << group << " destroyed twice or never spawned";
        alive.erase(it);
        ++destroyed;
    }
    void setVelocity(int sceneBody, Vec2 linearVelocity, float angularVelocity) override {
        driven.push_back(sceneBody);
        velocities.push_back({linearVelocity, angularVelocity});
    }
    struct Velocity {
        Vec2 linear;
        float angular;
    };
    int bodies = 0, joints = 0, destroyed = 0;
    std::vector<int> driven;
    std::vector<Velocity> velocities;
    std::vector<Group> alive;
    Group next = 0;
};

// --- washer, compounds, junkyard: built as Box2D v3's benchmark builds them ---

// Steps the scene's world (with its script, if any) and returns its non-static bodies.
std::vector<BodySample> afterSteps(const Scene& scene, int steps) {
    const auto stepper = crosscheck::makeStepper(Engine::Perpdot, scene);
    for (int i = 0; i < steps; ++i) stepper->step();
    std::vector<BodySample> out;
    stepper->sample(out);
    return out;
}

// A kinematic drum of 36 ring blocks and 4 paddles, 8,100 boxes of 0.2 m inside its paddles' reach.
TEST(BenchScenes, WasherIsADrumOf40ShapesHolding8100Boxes) {
    const Scene s = findScene("washer");
    EXPECT_EQ(s.steps, 500);
    ASSERT_EQ(s.bodies.size(), 1u + 90u * 90u);
    const SceneBody& drum = s.bodies[0];
    EXPECT_EQ(drum.name, "container");
    EXPECT_EQ(drum.type, BodyType::Kinematic);
    EXPECT_FLOAT_EQ(drum.angularVelocity, 25.0f * pi / 180.0f);
    ASSERT_EQ(drum.shapes.size(), 36u + 4u);
    for (const SceneShape& shape : drum.shapes) {
        ASSERT_EQ(shape.vertices.size(), 4u);
        for (const Vec2 v : shape.vertices) {
            EXPECT_GE(length(v), 14.0f - 1e-4f);
            EXPECT_LE(length(v), 18.0f + 1e-4f);
        }
    }
    EXPECT_EQ(countType(s, BodyType::Dynamic), 8100);
    for (size_t i = 1; i < s.bodies.size(); ++i) {
        EXPECT_EQ(s.bodies[i].shapes[0].halfExtents, (Vec2{0.1f, 0.1f}));
        EXPECT_LT(length(s.bodies[i].position - drum.position), 14.0f + 1e-3f);  // inside the paddles' circle
    }
}

// Turned for 4 s (100°: a paddle passes through the pile), no box leaves the ring of radius 16 m,
// and the paddles keep boxes moving: a box carried along the drum's wall at 25°/s moves at
// ω r ≈ 0.44·(14…16) ≈ 6–7 m/s, so far more than a few move faster than 0.1 m/s.
TEST(BenchScenes, WasherKeepsItsBoxesInsideAndMoving) {
    const Scene s = findScene("washer");
    const std::vector<BodySample> bodies = afterSteps(s, 240);
    ASSERT_EQ(bodies.size(), 1u + 8100u);
    const Vec2 center = bodies[0].center;
    int outside = 0, moving = 0;
    for (size_t i = 1; i < bodies.size(); ++i) {
        outside += length(bodies[i].center - center) > 16.0f ? 1 : 0;
        moving += length(bodies[i].state.linearVelocity) > 0.1f ? 1 : 0;
    }
    EXPECT_EQ(outside, 0);
    EXPECT_GT(moving, 8100 / 10);
}

// 3,000 bodies of two triangles each in 20 columns; the bin's floor of 81 boxes and walls of
// 100 boxes; the catching segment 80 m below.
TEST(BenchScenes, CompoundsAre3000PairsOfTrianglesAboveABin) {
    const Scene s = findScene("compounds");
    EXPECT_EQ(s.steps, 500);
    ASSERT_EQ(s.bodies.size(), 2u + 3000u);
    EXPECT_EQ(s.bodies[0].name, "ground");
    EXPECT_EQ(s.bodies[0].shapes.size(), 81u + 2u * 100u);
    EXPECT_EQ(s.bodies[1].shapes[0].kind, SceneShape::Kind::Segment);
    EXPECT_EQ(countType(s, BodyType::Dynamic), 3000);
    for (size_t i = 2; i < s.bodies.size(); ++i) {
        ASSERT_EQ(s.bodies[i].shapes.size(), 2u);
        for (const SceneShape& triangle : s.bodies[i].shapes) {
            EXPECT_EQ(triangle.vertices.size(), 3u);
            EXPECT_FLOAT_EQ(triangle.friction, 0.5f);
            EXPECT_FLOAT_EQ(triangle.density, 1.0f);
        }
        EXPECT_LT(std::abs(s.bodies[i].position.x), 40.0f - 1.5f);  // clear of the walls
    }
}

// After 5 s the lower rows have landed: every body is still between the walls and above the
// floor's top (y = 0.5), none fell through the floor or over a wall onto the catcher.
TEST(BenchScenes, CompoundsStayInTheirBin) {
    const std::vector<BodySample> bodies = afterSteps(findScene("compounds"), 300);
    ASSERT_EQ(bodies.size(), 3000u);
    for (size_t i = 0; i < bodies.size(); ++i) {
        EXPECT_LT(std::abs(bodies[i].center.x), 39.5f) << "body " << i;
        EXPECT_GT(bodies[i].center.y, 0.5f) << "body " << i;
    }
}

// 8,000 pentagons (five vertices on a circle of 0.25 m) and a kinematic pusher in a bin whose
// floor is 161 boxes and walls 50 each.
TEST(BenchScenes, JunkyardIs8000PentagonsAndAPusherInABin) {
    const Scene s = findScene("junkyard");
    EXPECT_EQ(s.steps, 800);
    ASSERT_EQ(s.bodies.size(), 1u + 8000u + 1u);
    EXPECT_EQ(s.bodies[0].shapes.size(), 161u + 2u * 50u);
    EXPECT_EQ(countType(s, BodyType::Dynamic), 8000);
    for (size_t i = 1; i <= 8000; ++i) {
        ASSERT_EQ(s.bodies[i].shapes[0].vertices.size(), 5u);
        for (const Vec2 v : s.bodies[i].shapes[0].vertices) EXPECT_NEAR(length(v), 0.25f, 1e-6f);
    }
    EXPECT_EQ(s.bodies.back().name, "pusher");
    EXPECT_EQ(s.bodies.back().type, BodyType::Kinematic);
}

// The script drives the pusher (scene body 8001) so that after step n it is at x = 60 sin(0.2 t_n):
// the velocities, times the step, sum to that path.
TEST(BenchScenes, JunkyardScriptSweepsThePusherAlong60SinOfAFifthOfTheTime) {
    const auto script = makeSceneScript("junkyard");
    ASSERT_NE(script, nullptr);
    RecordingEditor editor;
    const float h = 1.0f / 60.0f;
    double x = 0.0;
    for (int step = 0; step < 800; ++step) {
        const size_t before = editor.velocities.size();
        script->beforeStep(step, editor);
        if (editor.velocities.size() > before) {
            EXPECT_EQ(editor.driven.back(), 8001);
            EXPECT_EQ(editor.velocities.back().linear.y, 0.0f);
            x += double(editor.velocities.back().linear.x) * h;
        }
        EXPECT_NEAR(x, 60.0 * std::sin(0.2 * h * step), 2e-3) << "step " << step;
    }
    EXPECT_EQ(editor.velocities.size(), 799u);  // every step but the first, where it starts at rest
}

// In both engines the pusher follows its path, and after 4 s of pushing nothing has left the bin.
TEST(BenchScenes, JunkyardPusherFollowsItsPathAndTheJunkStaysInTheBin) {
    const Scene s = findScene("junkyard");
    const int steps = 240;
    const float h = 1.0f / 60.0f;
    const std::vector<BodySample> bodies = afterSteps(s, steps);
    ASSERT_EQ(bodies.size(), 8001u);
    // Driven before steps 1 … steps-1, it ends where the path is at step steps-1.
    EXPECT_NEAR(bodies.back().state.position.x, 60.0f * std::sin(0.2f * h * float(steps - 1)), 1e-2f);
    for (size_t i = 0; i + 1 < bodies.size(); ++i) {
        EXPECT_LT(std::abs(bodies[i].center.x), 80.0f) << "body " << i;
        EXPECT_GT(bodies[i].center.y, 0.0f) << "body " << i;
    }
    const auto box2d = crosscheck::makeStepper(Engine::Box2D, s);
    for (int i = 0; i < 3; ++i) box2d->step();
    std::vector<BodySample> b;
    box2d->sample(b);
    EXPECT_NEAR(b.back().state.position.x, 60.0f * std::sin(0.2f * h * 2.0f), 1e-5f);
}

TEST(BenchScenes, RoundTripThroughJson) {
    for (const char* name : {"bench_tumbler", "smash", "ragdoll_rain", "spinner", "joint_rack", "distance_net", "motor_swarm",
                             "washer", "compounds", "junkyard"}) {
        const Scene s = findScene(name);
        EXPECT_EQ(parseScene(toJson(s)), s) << name;
    }
}

TEST(RagdollRainScript, KeepsUpTo1000RagdollsEachLiving320Steps) {
    const auto script = makeSceneScript("ragdoll_rain");
    RecordingEditor editor;
    size_t mostAlive = 0;
    for (int step = 0; step < 1000; ++step) {
        const int before = editor.next;
        script->beforeStep(step, editor);
        EXPECT_EQ(editor.next - before, step % 8 == 0 ? 5 : 0) << "step " << step;  // one group per shelf
        mostAlive = std::max(mostAlive, editor.alive.size());
        if (step == 320) {
            EXPECT_EQ(editor.alive.front(), 5);  // the first column (groups 0-4) is gone
        }
    }
    EXPECT_EQ(mostAlive * 5, 1000u);  // groups of five ragdolls
    EXPECT_EQ(editor.next, 125 * 5);  // 125 columns spawned
    EXPECT_EQ(editor.destroyed, 85 * 5);
    EXPECT_EQ(editor.bodies, editor.next * 5 * ragdollBodyCount);
    EXPECT_EQ(editor.joints, editor.next * 5 * ragdollJointCount);
}

// Spawns a ragdoll at steps 0 and 3, destroys the first at step 6, spawns a third at step 8.
class SpawnAndDestroy final : public SceneScript {
public:
    void beforeStep(int step, SceneEditor& editor) override {
        Scene figure;
        addRagdoll(figure, {2.0f * float(step), 5.0f});
        if (step == 0) first_ = editor.spawn(figure);
        if (step == 3 || step == 8) editor.spawn(figure);
        if (step == 6) editor.destroy(first_);
    }
    std::unique_ptr<SceneScript> clone() const override { return std::make_unique<SpawnAndDestroy>(*this); }

private:
    SceneEditor::Group first_ = -1;
};

TEST(SceneScript, SpawnsAndDestroysTheSameBodiesInBothEngines) {
    Scene scene;
    scene.bodies.push_back({.name = "ground", .type = BodyType::Static, .position = {0.0f, -1.0f},
                            .shapes = {{.kind = SceneShape::Kind::Box, .halfExtents = {40.0f, 1.0f}}}});
    scene.bodies.push_back({.name = "ball", .position = {-5.0f, 2.0f}, .shapes = {{.radius = 0.5f}}});
    const auto perpdot = crosscheck::makeStepper(Engine::Perpdot, scene, std::make_unique<SpawnAndDestroy>());
    const auto box2d = crosscheck::makeStepper(Engine::Box2D, scene, std::make_unique<SpawnAndDestroy>());
    const int expected[] = {11, 11, 11, 21, 21, 21, 11, 11, 21, 21};  // after steps 0..9: the ball and the ragdolls
    std::vector<BodySample> p, b;
    for (int step = 0; step < 10; ++step) {
        perpdot->step();
        box2d->step();
        perpdot->sampleAll(p);
        box2d->sampleAll(b);
        ASSERT_EQ(p.size(), size_t(expected[step])) << "step " << step;
        ASSERT_EQ(b.size(), p.size()) << "step " << step;
        for (size_t i = 0; i < p.size(); ++i) EXPECT_LT(length(p[i].center - b[i].center), 0.01f) << "step " << step << " body " << i;
        perpdot->sample(p);
        EXPECT_EQ(p.size(), 1u);  // sample(): the scene's own bodies only
    }
    EXPECT_NEAR(p[0].center.x, -5.0f, 1e-6f);
}

class DestroyTwice final : public SceneScript {
public:
    void beforeStep(int step, SceneEditor& editor) override {
        Scene figure;
        addRagdoll(figure, {0.0f, 5.0f});
        if (step == 0) group_ = editor.spawn(figure);
        if (step >= 1) editor.destroy(group_);
    }
    std::unique_ptr<SceneScript> clone() const override { return std::make_unique<DestroyTwice>(*this); }

private:
    SceneEditor::Group group_ = -1;
};

TEST(SceneScript, DestroyingAGroupTwiceIsAnError) {
    for (const Engine engine : {Engine::Perpdot, Engine::Box2D}) {
        const auto stepper = crosscheck::makeStepper(engine, Scene{}, std::make_unique<DestroyTwice>());
        stepper->step();
        stepper->step();
        try {
            stepper->step();
            ADD_FAILURE() << "no error";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("group 0"), std::string::npos) << e.what();
        }
    }
}

TEST(SceneScript, RagdollRainSpawnsAlikeInBothEngines) {
    const Scene scene = findScene("ragdoll_rain");
    const auto perpdot = crosscheck::makeStepper(Engine::Perpdot, scene);
    const auto box2d = crosscheck::makeStepper(Engine::Box2D, scene);
    std::vector<BodySample> p, b;
    for (int step = 0; step < 9; ++step) perpdot->step(), box2d->step();
    perpdot->sampleAll(p);
    box2d->sampleAll(b);
    EXPECT_EQ(p.size(), 2u * 25u * ragdollBodyCount);  // columns spawned at steps 0 and 8
    ASSERT_EQ(b.size(), p.size());
    for (size_t i = 0; i < p.size(); ++i) EXPECT_LT(length(p[i].center - b[i].center), 0.01f) << "body " << i;
}

// --- stability figures ---

std::vector<BodySample> samplesOf(const Scene& scene) {
    std::vector<BodySample> out;
    crosscheck::makeStepper(Engine::Perpdot, scene)->sampleAll(out);
    return out;
}

TEST(BenchStability, ABodyOutsideTheTumblerHasEscaped) {
    const Scene scene = findScene("bench_tumbler");
    const StabilityProbe probe(scene);
    EXPECT_STREQ(probe.label(), "escaped");
    EXPECT_STREQ(probe.unit(), "bodies");
    const std::vector<BodySample> first = samplesOf(scene);
    std::vector<BodySample> last = first;
    EXPECT_EQ(probe.measure(first, last), 0.0f);
    last[1].center = {30.0f, 10.0f};  // beside the box
    EXPECT_EQ(probe.measure(first, last), 1.0f);
    // Just the container (the first moving body) and one box near its corner, local (9.8, 9.8):
    // inside while the container is square; outside once it has turned 45°, when the corner's
    // direction points at the middle of a wall.
    std::vector<BodySample> turned = {first[0], {.center = {9.8f, 19.8f}}};
    EXPECT_EQ(probe.measure(first, turned), 0.0f);
    turned[0].state.angle = pi / 4.0f;
    EXPECT_EQ(probe.measure(first, turned), 1.0f);
}

TEST(BenchStability, ABodyOutsideTheSpinnersLoopHasEscaped) {
    const Scene scene = findScene("spinner");
    const StabilityProbe probe(scene);
    const std::vector<BodySample> first = samplesOf(scene);
    std::vector<BodySample> last = first;
    EXPECT_EQ(probe.measure(first, last), 0.0f);
    last[5].center = {0.0f, 32.0f + 39.5f};  // just inside the top of the loop
    EXPECT_EQ(probe.measure(first, last), 0.0f);
    last[5].center = {0.0f, -8.5f};  // just below its bottom
    last[7].center = {41.0f, 32.0f};
    EXPECT_EQ(probe.measure(first, last), 2.0f);
}

TEST(BenchStability, MomentumErrorIsTheChangeOverTheInitialMomentum) {
    const Scene scene{.name = "smash", .gravity = {0.0f, 0.0f}};
    const StabilityProbe probe(scene);
    EXPECT_STREQ(probe.label(), "momentum error");
    const std::vector<BodySample> first = {{.state = {.linearVelocity = {3.0f, 0.0f}}, .mass = 2.0f},
                                           {.state = {.linearVelocity = {0.0f, 0.0f}}, .mass = 4.0f}};  // p0 = (6, 0)
    std::vector<BodySample> last = first;
    EXPECT_EQ(probe.measure(first, last), 0.0f);
    last[0].state.linearVelocity = {1.0f, 0.0f};  // momentum passed on exactly: (2 + 4) = 6
    last[1].state.linearVelocity = {1.0f, 0.0f};
    EXPECT_NEAR(probe.measure(first, last), 0.0f, 1e-7f);
    last[1].state.linearVelocity = {1.0f, 0.75f};  // Δp = (0, 3): 50 % of p0
    EXPECT_NEAR(probe.measure(first, last), 0.5f, 1e-6f);
}

TEST(BenchStability, BelowTheFloorCountsBodiesUnderTheLowestShelf) {
    const Scene scene = findScene("ragdoll_rain");
    const StabilityProbe probe(scene);
    EXPECT_STREQ(probe.label(), "below floor");
    const std::vector<BodySample> last = {{.center = {0.0f, 0.5f}}, {.center = {3.0f, -0.1f}}, {.center = {-90.0f, 46.0f}}};
    EXPECT_EQ(probe.measure({}, last), 1.0f);
}

TEST(BenchStability, WasherCountsBoxesOutsideItsDrumAndTheBinScenesBodiesBelowTheirFloor) {
    EXPECT_STREQ(StabilityProbe(findScene("washer")).label(), "escaped");
    for (const char* name : {"junkyard", "compounds"}) {
        const StabilityProbe probe(findScene(name));
        EXPECT_STREQ(probe.label(), "below floor") << name;
        // the floor is the bin's (boxes centred on y = 0), not compounds' catcher 80 m below
        const std::vector<BodySample> last = {{.center = {0.0f, 0.3f}}, {.center = {45.0f, -79.0f}}};
        EXPECT_EQ(probe.measure({}, last), 1.0f) << name;
    }
}

TEST(BenchStability, OtherScenesMeasureHowFarTheTopBodyFell) {
    const Scene scene = findScene("large_pyramid");
    const StabilityProbe probe(scene);
    EXPECT_STREQ(probe.label(), "top fell");
    EXPECT_STREQ(probe.unit(), "m");
    const std::vector<BodySample> first = samplesOf(scene);
    std::vector<BodySample> last = first;
    last.back().state.position.y -= 0.25f;  // the top box is the last one built
    EXPECT_FLOAT_EQ(probe.measure(first, last), 0.25f);
}

TEST(BenchStability, AContainerSceneWithoutAContainerIsAnError) {
    Scene scene = findScene("spinner");
    scene.bodies[0].name = "loop";
    scene.joints[0].bodyA = "loop";
    EXPECT_THROW(StabilityProbe{scene}, Error);
}

}  // namespace
}  // namespace perpdot
