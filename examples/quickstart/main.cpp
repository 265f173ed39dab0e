// perpdot quick start: a box falls onto the ground and comes to rest.
#include <cmath>
#include <cstdio>

#include <perpdot/perpdot.hpp>

int main() {
    using namespace perpdot;
    World world({.gravity = {0.0f, -10.0f}});

    // Static ground: a 40 m x 1 m box whose top face is at y = 0.
    const BodyId ground = world.createBody({.type = BodyType::Static, .position = {0.0f, -0.5f}});
    world.createShape(ground, {.friction = 0.6f}, makeBox(20.0f, 0.5f));

    // A dynamic 1 m box, 4 m up; its mass and inertia come from its shape's density (kg/m²).
    const BodyId box = world.createBody({.type = BodyType::Dynamic, .position = {0.0f, 4.0f}});
    world.createShape(box, {.density = 1.0f, .friction = 0.6f}, makeBox(0.5f, 0.5f));

    for (int i = 0; i < 60; ++i) world.step(1.0f / 60.0f);  // one second

    const Vec2 p = world.position(box);
    std::printf("box at (%.3f, %.3f), mass %.2f kg\n", p.x, p.y, world.mass(box));
    // It fell 3.5 m in 0.84 s and now rests on the ground, its centre half a metre up.
    const bool resting = std::fabs(p.y - 0.5f) < 0.05f && std::fabs(p.x) < 0.01f;
    return resting ? 0 : 1;
}
