// Total mechanical energy of the dynamic bodies: E = Σ ½ m|v|² + ½ I ω² − m (gravityScale g)·c.
#pragma once

#include "perpdot/world.hpp"

namespace perpdot::demo {

inline float totalEnergy(const World& world) {
    const Vec2 g = world.settings().gravity;
    float energy = 0.0f;
    for (BodyId body : world.bodies()) {
        if (world.bodyType(body) != BodyType::Dynamic) continue;
        const float m = world.mass(body);
        const float omega = world.angularVelocity(body);
        energy += 0.5f * m * lengthSquared(world.linearVelocity(body)) +
                  0.5f * world.rotationalInertia(body) * omega * omega -
                  m * world.gravityScale(body) * dot(g, world.worldCenter(body));
    }
    return energy;
}

}  // namespace perpdot::demo
