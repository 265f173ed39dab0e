// Rollback-grade snapshots: a run that saves, runs ahead, restores and re-simulates (what rollback
// netcode does every frame) must see the same future as a run that never snapshotted — state hash
// and every event, each step — at over 1,000 restore points drawn with a fixed seed across every
// built-in scene (scene actions, behaviours and scripts included) and test::jointZoo() (every
// joint type, the filter joint added here, sensor, bullet). Between running ahead and restoring, the world is sometimes
// disturbed (a body destroyed, another created), so restore must replace all of it.
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "joint_zoo.hpp"
#include "physics_scenes.hpp"
#include "perpdot/error.hpp"
#include "perpdot/feature_scenes.hpp"
#include "perpdot/scene.hpp"
#include "perpdot/state_hash.hpp"
#include "scene/build_world.hpp"
#include "scene/scene_script.hpp"

namespace perpdot {
namespace {

using Bytes = std::vector<uint8_t>;

#if defined(__SANITIZE_ADDRESS__)
constexpr int pointScale = 4;  // the sanitizer build runs a quarter of the points (about 260)
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr int pointScale = 4;
#else
constexpr int pointScale = 1;
#endif
#else
constexpr int pointScale = 1;
#endif

// The handles each event holds.
template <class Event>
constexpr auto idMembers(const Event*) {
    return std::tuple{&Event::shapeA, &Event::shapeB};
}
constexpr auto idMembers(const SensorBeginTouchEvent*) {
    return std::tuple{&SensorBeginTouchEvent::sensorShape, &SensorBeginTouchEvent::visitorShape};
}
constexpr auto idMembers(const SensorEndTouchEvent*) {
    return std::tuple{&SensorEndTouchEvent::sensorShape, &SensorEndTouchEvent::visitorShape};
}

// FNV-1a over the bytes of the step's events (their structs have no padding), with the World
// identity of their handles cleared: the runs compared are Worlds of their own.
template <class T>
void hashEvents(uint64_t& h, std::span<const T> events) {
    for (T e : events) {
        std::apply([&](auto... member) { (((e.*member).world = 0), ...); }, idMembers(&e));
        unsigned char bytes[sizeof(T)];
        std::memcpy(bytes, &e, sizeof(T));
        for (unsigned char b : bytes) h = (h ^ b) * 0x100000001b3ull;
    }
    h = (h ^ events.size()) * 0x100000001b3ull;
}

struct Frame {
    uint64_t state = 0, events = 0;
    bool operator==(const Frame&) const = default;
};

Frame frameOf(const World& w) {
    uint64_t h = 0xcbf29ce484222325ull;
    const ContactEvents contact = w.contactEvents();
    const SensorEvents sensor = w.sensorEvents();
    hashEvents(h, contact.beginEvents);
    hashEvents(h, contact.endEvents);
    hashEvents(h, contact.hitEvents);
    hashEvents(h, sensor.beginEvents);
    hashEvents(h, sensor.endEvents);
    return {stateHash(w), h};
}

// A scene run as a game runs it: its world with behaviour, its actions, and its script, whose
// spawns and destroys go through this editor.
class SceneRun final : private SceneEditor {
public:
    explicit SceneRun(const std::string& name) : built_(buildWorldWithBehaviour(findScene(name))), script_(makeSceneScript(name)) {}
    explicit SceneRun(World world) : built_{.world = std::move(world)} {}

    void step() {
        if (script_) script_->beforeStep(built_.stepIndex, *this);
        built_.step();
    }
    World& world() { return built_.world; }

    // What a rollback saves: the world (full, or compact against a baseline), the step count
    // (scene actions), the script and its groups.
    struct Saved {
        Bytes world;
        Bytes compact;
        const Bytes* baseline = nullptr;
        int stepIndex = 0;
        std::unique_ptr<SceneScript> script;
        std::vector<std::vector<BodyId>> groups;
    };
    Saved save(const Bytes* baseline) const {
        return {baseline ? Bytes{} : built_.world.snapshot(), baseline ? built_.world.compactSnapshot(*baseline) : Bytes{},
                baseline, built_.stepIndex, script_ ? script_->clone() : nullptr, groups_};
    }
    void restore(const Saved& saved) {
        if (saved.baseline) built_.world.restoreCompact(*saved.baseline, saved.compact);
        else built_.world.restore(saved.world);
        built_.stepIndex = saved.stepIndex;
        script_ = saved.script ? saved.script->clone() : nullptr;
        groups_ = saved.groups;
    }

private:
    Group spawn(const Scene& fragment) override {
        groups_.push_back(addToWorld(built_.world, fragment).bodies);
        return Group(groups_.size() - 1);
    }
    void destroy(Group group) override {
        for (BodyId body : groups_[size_t(group)]) built_.world.destroyBody(body);
        groups_[size_t(group)].clear();
    }
    void setVelocity(int sceneBody, Vec2 linearVelocity, float angularVelocity) override {
        built_.world.setLinearVelocity(built_.bodies.at(size_t(sceneBody)), linearVelocity);
        built_.world.setAngularVelocity(built_.bodies.at(size_t(sceneBody)), angularVelocity);
    }

    SceneWorld built_;
    std::unique_ptr<SceneScript> script_;
    std::vector<std::vector<BodyId>> groups_;
};

// Steps and restore points per scene: the benchmark scenes (thousands of bodies) get a few.
struct Plan {
    int steps = 0, points = 0;
};

Plan planFor(const std::string& name, int sceneSteps) {
    if (name == "many_pyramids" || name == "smash" || name == "spinner" || name == "joint_grid" || name == "large_pyramid" ||
        name == "stress_large_pile" || name == "washer" || name == "compounds" || name == "junkyard")
        return {12, 2};
    if (name == "ragdoll_rain") return {40, 4};  // past a few spawns
    if (name == "bench_tumbler") return {24, 3};
    if (name == "joint_rack" || name == "distance_net" || name == "motor_swarm") return {40, 4};
    if (name == "vertical_stack") return {600, 40};  // asleep from about step 300 on
    if (name == "bullet_wall") return {40, 20};      // the bullets hit within the first steps
    return {std::min(sceneSteps, 420), 38};
}

struct Coverage {
    int points = 0, compact = 0, withSleepingBodies = 0, withEvents = 0, editedBeforeSave = 0, disturbedBeforeRestore = 0;
};

// One restore point: save after step saveAt (0-based), run `ahead` steps, restore, re-simulate.
struct Point {
    int saveAt = 0, ahead = 1;
    bool edit = false;     // the user edits the world between the step and the save (in both runs)
    bool disturb = false;  // the world is changed after running ahead, before restoring
    bool compact = false;  // saved as a compact snapshot against a baseline taken a few points earlier
};

std::vector<Point> drawPoints(Plan plan, std::mt19937& rng) {
    const int points = std::max(1, plan.points / pointScale);
    const int stride = plan.steps / points;  // each point draws its save step and distance in its stride
    std::vector<Point> drawn;
    for (int k = 0; k < points; ++k) {
        Point p;
        p.ahead = 1 + int(rng() % unsigned(std::min(12, std::max(1, stride / 2))));
        p.saveAt = k * stride + int(rng() % unsigned(std::max(1, stride - p.ahead)));
        p.edit = rng() % 4 == 0;
        p.disturb = rng() % 3 == 0;
        p.compact = k % 2 == 1;
        drawn.push_back(p);
    }
    return drawn;
}

// Between two steps, as a game would: the newest dynamic body loses a shape (the end events of its
// contacts are reported by the next step), or gets an impulse and a force (force accumulators).
// Bodies stay: scene actions and scripts name them.
void editBetweenSteps(World& w, int step) {
    const std::vector<BodyId> bodies = w.bodies();
    for (auto it = bodies.rbegin(); it != bodies.rend(); ++it) {
        if (w.bodyType(*it) != BodyType::Dynamic || w.shapes(*it).empty()) continue;
        if (step % 2 == 0) {
            w.destroyShape(w.shapes(*it).front());
        } else {
            w.applyLinearImpulseToCenter(*it, {0.5f, 2.0f});
            w.applyForce(*it, {0, 30}, w.worldCenter(*it) + Vec2{0.1f, 0});
        }
        return;
    }
}

void disturb(World& w, std::mt19937& rng) {
    if (const std::vector<BodyId> bodies = w.bodies(); !bodies.empty()) w.destroyBody(bodies[rng() % bodies.size()]);
    const BodyId extra = w.createBody({.type = BodyType::Dynamic, .position = {0, 3}});
    w.createShape(extra, {}, Circle{{0, 0}, 0.3f});
}

bool anyEvents(const World& w) {
    const ContactEvents c = w.contactEvents();
    const SensorEvents s = w.sensorEvents();
    return !c.beginEvents.empty() || !c.endEvents.empty() || !c.hitEvents.empty() || !s.beginEvents.empty() ||
           !s.endEvents.empty();
}

bool anySleeping(const World& w) {
    for (BodyId body : w.bodies())
        if (w.bodyType(body) == BodyType::Dynamic && !w.isAwake(body)) return true;
    return false;
}

// Runs `make()` once without snapshots, recording every frame, then again through the restore
// points: save after step saveAt, run ahead (checked against the record), maybe disturb, restore,
// re-simulate the same steps (checked again; the bytes must equal those of the run ahead).
template <class Make>
void checkRollback(const std::string& name, Make make, Plan plan, std::mt19937& rng, Coverage& coverage) {
    const std::vector<Point> points = drawPoints(plan, rng);
    const auto edits = [&](int step) {
        for (const Point& p : points)
            if (p.saveAt == step) return p.edit;
        return false;
    };
    std::vector<Frame> reference;
    {
        std::unique_ptr<SceneRun> run = make();
        for (int s = 0; s < plan.steps; ++s) {
            run->step();
            reference.push_back(frameOf(run->world()));
            if (edits(s)) editBetweenSteps(run->world(), s);
        }
    }
    std::unique_ptr<SceneRun> run = make();
    int s = 0;
    Bytes baseline;
    for (const Point& point : points) {
        for (; s <= point.saveAt; ++s) {
            run->step();
            ASSERT_EQ(frameOf(run->world()), reference[size_t(s)]) << name << " step " << s;
        }
        if (point.edit) editBetweenSteps(run->world(), point.saveAt);
        if (baseline.empty() || &point - points.data() == 8) baseline = run->world().baselineSnapshot();
        const SceneRun::Saved saved = run->save(point.compact ? &baseline : nullptr);
        for (int i = 0; i < point.ahead; ++i) {
            run->step();
            ASSERT_EQ(frameOf(run->world()), reference[size_t(s + i)]) << name << " running ahead, step " << s + i;
        }
        const Bytes atEnd = run->world().snapshot();
        if (point.disturb) disturb(run->world(), rng);
        run->restore(saved);
        bool events = false;
        for (int i = 0; i < point.ahead; ++i) {
            run->step();
            ASSERT_EQ(frameOf(run->world()), reference[size_t(s + i)])
                << name << " restored after step " << point.saveAt << ", re-simulated step " << s + i;
            events = events || anyEvents(run->world());
        }
        ASSERT_EQ(run->world().snapshot(), atEnd) << name << " restored after step " << point.saveAt << ": bytes after re-simulation";
        s += point.ahead;
        ++coverage.points;
        coverage.withSleepingBodies += anySleeping(run->world()) ? 1 : 0;
        coverage.withEvents += events ? 1 : 0;
        coverage.compact += point.compact ? 1 : 0;
        coverage.editedBeforeSave += point.edit ? 1 : 0;
        coverage.disturbedBeforeRestore += point.disturb ? 1 : 0;
    }
}

TEST(SnapshotRollback, EveryRestorePointReplaysTheSameFuture) {
    std::mt19937 rng(16003);
    Coverage coverage;
    for (const BuiltinScene& scene : builtinScenes()) {
        const Scene made = scene.make();
        checkRollback(scene.name, [&] { return std::make_unique<SceneRun>(scene.name); }, planFor(scene.name, made.steps), rng,
                      coverage);
        if (HasFatalFailure()) return;
    }
    // The zoo, plus the filter joint (not in the scene format): two overlapping boxes that fall
    // through each other onto the ground.
    const auto zooWithFilter = [] {
        World world = test::jointZoo();
        const BodyId a = world.createBody({.type = BodyType::Dynamic, .position = {24.0f, 3.0f}});
        const BodyId b = world.createBody({.type = BodyType::Dynamic, .position = {24.3f, 3.4f}, .angle = 0.3f});
        world.createShape(a, {}, makeBox(0.5f, 0.5f));
        world.createShape(b, {}, makeBox(0.5f, 0.5f));
        world.createJoint(FilterJointDef{.bodyA = a, .bodyB = b});
        return std::make_unique<SceneRun>(std::move(world));
    };
    checkRollback("joint_zoo", zooWithFilter, {240, 60}, rng, coverage);
    // The zoo with its joints changed at run time (World::enableLimit, setLimits, enableMotor,
    // the bounds, springs and lengths), a friction joint and a breakable hinge added: snapshots
    // carry every such setting and the step-summed impulses start afresh each step.
    const auto zooChanged = [] {
        World world = test::jointZoo();
        for (JointId joint : world.joints()) {
            switch (world.jointType(joint)) {
                case JointType::Revolute:
                    world.setLimits(joint, -0.5f, 0.3f);
                    world.setMaxMotorTorque(joint, 5.0f);
                    break;
                case JointType::Prismatic:
                    world.enableLimit(joint, false);
                    world.setMaxMotorForce(joint, 20.0f);
                    break;
                case JointType::Distance:
                    world.setLengthRange(joint, 0.5f, 2.5f);
                    world.setSpringHertz(joint, 4.0f);
                    break;
                case JointType::Weld: world.setSpringDampingRatio(joint, 1.5f); break;
                case JointType::Wheel:
                    world.enableMotor(joint, false);
                    world.setSpringHertz(joint, 3.0f);
                    break;
                case JointType::Motor: world.setLinearOffset(joint, {9.0f, 3.0f}); break;
                default: break;
            }
        }
        const BodyId ground = world.jointBodyA(world.joints().front());
        const BodyId puck = world.createBody({.type = BodyType::Dynamic, .position = {-16.0f, 3.0f}, .linearVelocity = {2.0f, 1.0f},
                                              .angularVelocity = 3.0f});
        world.createShape(puck, {}, Circle{{0, 0}, 0.3f});
        world.createJoint(FrictionJointDef{.bodyA = ground, .bodyB = puck, .maxForce = 3.0f, .maxTorque = 0.2f});
        const BodyId sign = world.createBody({.type = BodyType::Dynamic, .position = {-18.0f, 6.0f}});
        world.createShape(sign, {}, makeBox(0.3f, 0.5f));
        const JointId hinge = world.createJoint(RevoluteJointDef{.bodyA = ground, .bodyB = sign, .localAnchorA = {-18.0f, 6.5f},
                                                                 .localAnchorB = {0.0f, 0.5f}});
        world.setJointBreakLimits(hinge, 40.0f, std::numeric_limits<float>::infinity());
        world.applyLinearImpulseToCenter(sign, {0.4f, 0.0f});
        return std::make_unique<SceneRun>(std::move(world));
    };
    checkRollback("joint_zoo_changed", zooChanged, {240, 60}, rng, coverage);
    EXPECT_GE(coverage.points * pointScale, 1000);
    EXPECT_GT(coverage.withSleepingBodies, 0);
    EXPECT_GT(coverage.withEvents, 0);
    EXPECT_GT(coverage.editedBeforeSave, 0);
    EXPECT_GT(coverage.disturbedBeforeRestore, 0);
    EXPECT_GT(coverage.compact, 0);
    std::printf("restore points: %d (%d compact, %d with sleeping bodies, %d with events re-simulated, %d edited before saving, %d "
                "disturbed before restoring)\n",
                coverage.points, coverage.compact, coverage.withSleepingBodies, coverage.withEvents, coverage.editedBeforeSave,
                coverage.disturbedBeforeRestore);
}

// Compact snapshots: far smaller than full ones when little changed, refused against another
// baseline, and refused (never crashing) when cut short or corrupted.
TEST(SnapshotRollback, CompactSnapshotsNeedTheirBaselineAndRefuseBadBytes) {
    SceneWorld built = buildWorld(findScene("pyramid"));
    for (int i = 0; i < 100; ++i) built.step();
    const Bytes baseline = built.world.baselineSnapshot();
    for (int i = 0; i < 8; ++i) built.step();
    const Bytes compact = built.world.compactSnapshot(baseline);
    const Bytes full = built.world.snapshot();
    EXPECT_LT(compact.size() * 4, full.size());
    const uint64_t hash = stateHash(built.world);

    World target;
    target.restoreCompact(baseline, compact);
    EXPECT_EQ(stateHash(target), hash);
    Bytes otherBaseline = baseline;
    otherBaseline.back() ^= 1;
    try {
        target.restoreCompact(otherBaseline, compact);
        ADD_FAILURE() << "a compact snapshot was accepted against another baseline";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("another baseline"), std::string::npos) << e.what();
    }
    for (size_t size = 0; size < compact.size(); size += 13)
        EXPECT_THROW(target.restoreCompact(baseline, std::span(compact.data(), size)), Error) << size;
    for (size_t i = 24; i < compact.size(); i += 37) {  // past the header: run lengths and XORed bytes
        Bytes bad = compact;
        bad[i] ^= 0x5A;
        try {
            target.restoreCompact(baseline, bad);  // may load: then it is a consistent world
            target.step(1.0f / 60);
        } catch (const Error&) {
        }
    }
    target.restoreCompact(baseline, compact);
    EXPECT_EQ(stateHash(target), hash);

    Bytes oldVersion = compact;
    oldVersion[8] = 4;  // the version (u32 after the magic): 4 wrote varint pairs, not nibble headers
    try {
        target.restoreCompact(baseline, oldVersion);
        ADD_FAILURE() << "a compact snapshot of format version 4 was accepted";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("version 4 is not supported"), std::string::npos) << e.what();
    }
}

// The rollback budget: at most 64 bytes per awake body in a compact snapshot of an
// 820-box pyramid with sleep off, every body awake, 8 steps after its baseline.
TEST(SnapshotRollback, CompactSnapshotOfAnAwakePyramidIsAtMost64BytesPerBody) {
    World world(WorldDef{.enableSleep = false});
    test::addGround(world, 0.0f, 30.0f);
    const std::vector<BodyId> boxes = test::addPyramid(world, 40);
    test::run(world, 120);
    const Bytes baseline = world.baselineSnapshot();
    test::run(world, 8);
    for (BodyId box : boxes) ASSERT_TRUE(world.isAwake(box));
    const Bytes compact = world.compactSnapshot(baseline);
    const double bytesPerBody = static_cast<double>(compact.size()) / static_cast<double>(boxes.size());
    std::printf("compact snapshot: %zu bytes, %.1f per awake body\n", compact.size(), bytesPerBody);
    EXPECT_LE(bytesPerBody, 64.0);
    EXPECT_GT(bytesPerBody, 8.0);  // every body moved a little: a near-empty delta would be a bug
}

}  // namespace
}  // namespace perpdot
