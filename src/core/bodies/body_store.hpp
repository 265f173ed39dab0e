// A body as the world stores it: its pose and velocity, mass properties, settings and sleep
// state, its shapes, and its links into the step. The body store is a Pool<Body> (pool.hpp),
// World::Impl::bodies; a BodyId is (index, generation) in it.
#pragma once

#include <cstdint>
#include <vector>

#include "core/base/pool.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct Body {
    uint32_t generation = 0;
    bool alive = false;
    BodyType type = BodyType::Static;
    // Beside the pose: the narrowphase asks every contact's bodies whether they are awake, then
    // reads their poses, so these share a cache line. (A body's solver slot during a step is
    // SolverBodies::bodySlots.)
    bool awake = true;
    bool enabled = true;   // World::setEnabled: false keeps it out of the step and the broadphase
    int jointCount = 0;    // joints attached (maintained by the joint store); beside the type, for
                           // the contact groups' per-step look at every awake body's kind
    Transform xf;          // origin frame
    float angle = 0;       // accumulated θ; xf.q = Rot(θ)
    Vec2 localCenter;      // centre of mass, body frame
    Vec2 center;           // centre of mass, world
    Vec2 v;                // velocity of the centre of mass
    float w = 0;           // angular velocity ω
    Vec2 force;            // accumulated this step
    float torque = 0;
    float mass = 0, invMass = 0;
    float inertia = 0, invInertia = 0;  // scalar I about the centre of mass
    float linearDamping = 0, angularDamping = 0, gravityScale = 1;
    bool fixedRotation = false, bullet = false, allowSleep = true;
    int islandNext = -1;   // next body of the island it fell asleep with
    float sleepTime = 0;
    void* userData = nullptr;
    std::vector<int> shapes;

    // Body{}, keeping the shape list's memory (Pool::restoreSlots).
    void resetKeepingMemory() {
        std::vector<int> keep = std::move(shapes);
        keep.clear();
        *this = Body{};
        shapes = std::move(keep);
    }

    // The origin frame of the pose (θ, c): q = Rot(θ), x = c − R(θ)·localCenter.
    Transform derivedTransform() const {
        const Rot q = Rot::fromAngle(angle);
        return {center - rotate(q, localCenter), q};
    }
};

// Wakes the body and the island it fell asleep with: bodies that slept together form a ring
// through islandNext (sleep.cpp), undone as they wake.
inline void wakeIsland(Pool<Body>& bodies, int index) {
    int i = index;
    do {
        Body& b = bodies[i];
        const int next = b.islandNext;
        b.islandNext = -1;
        if (b.type != BodyType::Static && b.enabled) {
            b.awake = true;
            b.sleepTime = 0.0f;
        }
        i = next;
    } while (i >= 0 && i != index);
}

// A body whose motion went non-finite, frozen where it is instead of spreading NaN: stopped,
// asleep until something wakes it, and counted in frozenBodies (stats().frozenBodies).
inline void freeze(Body& b, int& frozenBodies) {
    b.v = {};
    b.w = 0.0f;
    b.awake = false;
    b.sleepTime = 0.0f;
    ++frozenBodies;
}

}  // namespace perpdot
