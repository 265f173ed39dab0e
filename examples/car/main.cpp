// A car on a terrain, written the way a game uses perpdot: the ground is one chain given left to
// right (the way a level editor writes it); the car is a chassis on two sprung wheel joints with
// motors; it pushes two crates up a 15° hill and drives on over the crest. Exit status 0 when the
// car has crossed the hill upright and the crates were pushed uphill.
#include <cmath>
#include <cstdio>
#include <vector>

#include <perpdot/perpdot.hpp>

namespace {

using namespace perpdot;

constexpr float dt = 1.0f / 60.0f;

// Flat to x = 0, a 15° climb to x = 20, a plateau to x = 30, a 15° descent, flat again.
BodyId buildTerrain(World& world) {
    const float rise = 20.0f * std::tan(15.0f * 3.14159265f / 180.0f);  // 5.36 m
    const std::vector<Vec2> points{{-40.0f, 0.0f}, {0.0f, 0.0f}, {10.0f, 0.5f * rise}, {20.0f, rise}, {30.0f, rise},
                                   {40.0f, 0.5f * rise}, {50.0f, 0.0f}, {90.0f, 0.0f}};
    const BodyId ground = world.createBody({.type = BodyType::Static});
    world.createShape(ground, {.friction = 0.8f}, Chain{.vertices = points});
    return ground;
}

struct Car {
    BodyId chassis, rearWheel, frontWheel;
};

Car buildCar(World& world, Vec2 at) {
    Car car;
    car.chassis = world.createBody({.type = BodyType::Dynamic, .position = at});
    world.createShape(car.chassis, {.density = 5.0f}, makeBox(1.5f, 0.3f));
    for (float side : {-1.0f, 1.0f}) {
        const Vec2 hub{1.1f * side, -0.65f};
        const BodyId wheel = world.createBody({.type = BodyType::Dynamic, .position = at + hub});
        world.createShape(wheel, {.density = 1.0f, .friction = 0.9f}, Circle{.radius = 0.4f});
        world.createJoint(WheelJointDef{.bodyA = car.chassis, .bodyB = wheel, .localAnchorA = hub, .localAnchorB = {},
                                        .hertz = 4.0f, .dampingRatio = 0.7f, .enableMotor = true, .motorSpeed = -10.0f,
                                        .maxMotorTorque = 40.0f});
        (side < 0.0f ? car.rearWheel : car.frontWheel) = wheel;
    }
    return car;
}

}  // namespace

int main() {
    World world({.gravity = {0.0f, -10.0f}});
    buildTerrain(world);
    const Car car = buildCar(world, {-10.0f, 1.2f});
    // Two 0.6 m crates (0.36 kg each) resting on the foot of the hill, in the car's way.
    std::vector<BodyId> crates;
    const float slope = 15.0f * 3.14159265f / 180.0f;
    for (float x : {1.5f, 3.0f}) {
        const Vec2 center = Vec2{x, x * std::tan(slope)} + 0.3f * Vec2{-std::sin(slope), std::cos(slope)};
        crates.push_back(world.createBody({.type = BodyType::Dynamic, .position = center, .angle = slope}));
        world.createShape(crates.back(), {.density = 1.0f, .friction = 0.6f}, makeBox(0.3f, 0.3f));
    }

    float highestCrate = 0.0f, worstTilt = 0.0f;
    bool crossed = false, fellThrough = false;
    for (int frame = 0; frame < 60 * 30 && !crossed && !fellThrough; ++frame) {
        world.step(dt);
        for (BodyId crate : crates) highestCrate = std::max(highestCrate, world.position(crate).y);
        const Vec2 p = world.position(car.chassis);
        worstTilt = std::max(worstTilt, std::fabs(world.angle(car.chassis)));
        crossed = p.x > 45.0f;
        fellThrough = p.y < -1.0f;
    }
    const Vec2 p = world.position(car.chassis);
    std::printf("car: chassis at (%.2f, %.2f), worst tilt %.2f rad, crates pushed up to y %.2f m, %s\n", p.x, p.y,
                worstTilt, highestCrate, crossed ? "crossed the hill" : fellThrough ? "fell through the ground" : "did not cross");
    return crossed && worstTilt < 1.0f && highestCrate > 1.5f ? 0 : 1;
}
