// A small platformer on perpdot, written the way a game uses the engine: a character mover walks
// right across a level with a pit crossed on a moving platform, a one-way ledge jumped onto from
// below, a gate welded to its post that breaks when the character shoves it, and a goal sensor.
// The "player" is a few lines of game logic reading the world each frame. Exit status 0 when the
// character reaches the goal having ridden the platform, stood on the ledge and broken the gate.
#include <cmath>
#include <cstdio>

#include <perpdot/perpdot.hpp>

namespace {

using namespace perpdot;

constexpr float dt = 1.0f / 60.0f;
constexpr uint16_t oneWayCategory = 0x0002;

// A static box whose top face is at `top`, from x = left to x = right.
void addFloor(World& world, float left, float right, float top) {
    const BodyId floor = world.createBody({.type = BodyType::Static, .position = {0.5f * (left + right), top - 0.5f}});
    world.createShape(floor, {}, makeBox(0.5f * (right - left), 0.5f));
}

struct Level {
    BodyId platform;          // kinematic, shuttles across the pit (centre from 11.5 to 14.5, top at y = 0)
    ShapeId platformShape;
    JointId gateHinge;        // the weld holding the gate (24 N) to its post; breaks above 150 N
    ShapeId goal;             // sensor at the end of the level
};

Level buildLevel(World& world) {
    Level level;
    addFloor(world, -5.0f, 10.0f, 0.0f);   // start
    addFloor(world, 16.0f, 40.0f, 0.0f);   // after the pit (10 m to 16 m, 20 m deep)
    addFloor(world, -5.0f, 40.0f, -20.0f); // the pit's floor: falling in loses

    level.platform = world.createBody({.type = BodyType::Kinematic, .position = {11.5f, -0.25f}});
    level.platformShape = world.createShape(level.platform, {}, makeBox(1.5f, 0.25f));

    // A one-way ledge 1.2 m up: solid only from above for the mover (MoverDef::oneWayCategories).
    const BodyId ledge = world.createBody({.type = BodyType::Static, .position = {22.0f, 1.1f}});
    world.createShape(ledge, {.filter = {.category = oneWayCategory}}, makeBox(2.0f, 0.1f));

    // The gate: a 2 m plank standing on the floor, welded to a post; a shove breaks the weld.
    const BodyId post = world.createBody({.type = BodyType::Static, .position = {28.0f, 3.0f}});
    world.createShape(post, {}, makeBox(0.2f, 0.2f));
    const BodyId gate = world.createBody({.type = BodyType::Dynamic, .position = {28.0f, 1.6f}});
    world.createShape(gate, {.density = 5.0f}, makeBox(0.1f, 1.2f));
    level.gateHinge = world.createJoint(WeldJointDef{.bodyA = post, .bodyB = gate, .localAnchorA = {0.0f, -0.2f},
                                                     .localAnchorB = {0.0f, 1.2f}});
    world.setJointBreakLimits(level.gateHinge, 150.0f, 1.0e9f);

    const BodyId goalBody = world.createBody({.type = BodyType::Static, .position = {34.0f, 1.0f}});
    level.goal = world.createShape(goalBody, {.sensor = true}, makeBox(0.5f, 1.0f));
    return level;
}

// The platform shuttles at 2 m/s between x = 11.5 and x = 14.5 and rests 1 s at each end (a
// kinematic body moves at the velocity the game gives it).
struct PlatformDriver {
    float rest = 0.0f;       // seconds left at this end
    float direction = 1.0f;  // where it goes next
    void update(World& world, BodyId platform) {
        const float x = world.position(platform).x;
        const bool atEnd = (direction > 0.0f && x >= 14.5f) || (direction < 0.0f && x <= 11.5f);
        if (atEnd && rest <= 0.0f) rest = 1.0f, direction = -direction;
        rest -= dt;
        world.setLinearVelocity(platform, {rest > 0.0f ? 0.0f : 2.0f * direction, 0.0f});
    }
};

}  // namespace

int main() {
    World world({.gravity = {0.0f, -10.0f}});
    const Level level = buildLevel(world);
    const MoverDef def{.oneWayCategories = oneWayCategory};
    MoverState player = world.createMover(def, {0.0f, def.radius + def.halfHeight + def.skin});

    enum class Phase { Approach, Wait, Board, Ride, Run } phase = Phase::Approach;
    PlatformDriver driver{.direction = -1.0f};
    bool rodePlatform = false, stoodOnLedge = false, gateBroke = false, reachedGoal = false, fell = false;
    for (int frame = 0; frame < 60 * 40 && !reachedGoal && !fell; ++frame) {
        driver.update(world, level.platform);
        world.step(dt);
        for (const JointBreakEvent& e : world.jointEvents().breakEvents) gateBroke = gateBroke || e.joint == level.gateHinge;
        for (const SensorBeginTouchEvent& e : world.sensorEvents().beginEvents)
            reachedGoal = reachedGoal || (e.sensorShape == level.goal && e.visitorShape == player.shape);

        // The player's logic: wait at the pit's edge until the platform comes, board it, ride it
        // to the far side, jump onto the ledge, then run on.
        const float x = player.position.x, platformX = world.position(level.platform).x;
        const bool onPlatform = player.grounded && player.ground == level.platformShape;
        if (phase == Phase::Approach && x > 9.6f) phase = Phase::Wait;
        if (phase == Phase::Wait && platformX <= 11.5f) phase = Phase::Board;
        if (phase == Phase::Board && onPlatform) phase = Phase::Ride;
        if (phase == Phase::Ride && platformX >= 14.5f) phase = Phase::Run;
        MoverInput input{.walkSpeed = phase == Phase::Wait || phase == Phase::Ride ? 0.0f : 4.0f};
        input.jump = phase == Phase::Run && player.grounded && x > 18.6f && player.position.y < 1.0f;
        world.moveMover(def, player, input, dt);

        rodePlatform = rodePlatform || onPlatform;
        stoodOnLedge = stoodOnLedge || (player.grounded && player.position.y > 1.2f);
        fell = player.position.y < -5.0f;
    }
    std::printf("platformer: rode the platform %s, stood on the ledge %s, broke the gate %s, reached the goal %s (x %.2f)\n",
                rodePlatform ? "yes" : "no", stoodOnLedge ? "yes" : "no", gateBroke ? "yes" : "no",
                reachedGoal ? "yes" : "no", player.position.x);
    return rodePlatform && stoodOnLedge && gateBroke && reachedGoal ? 0 : 1;
}
