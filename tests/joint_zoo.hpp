// A world with one joint of every type (revolute with motor and limit, prismatic with limit,
// distance spring, weld, wheel with motor, motor, mouse), a sensor, a bullet, a ball that falls
// asleep and a box pile — built from the public API alone, for snapshot tests. The checked-in
// format-1 snapshots (tests/data/snapshot_v1/) were written from this world by the code of e7499b5.
#pragma once

#include "perpdot/world.hpp"

namespace perpdot::test {

inline World jointZoo() {
    World w;
    const BodyId ground = w.createBody({});
    w.createShape(ground, {}, Segment{{-30, 0}, {30, 0}});
    const auto box = [&](Vec2 p, float half) {
        const BodyId b = w.createBody({.type = BodyType::Dynamic, .position = p});
        w.createShape(b, {}, makeBox(half, half));
        return b;
    };
    // Revolute with motor and limit: an arm on a hinge.
    const BodyId arm = box({-12, 4}, 0.4f);
    w.createJoint(RevoluteJointDef{.bodyA = ground, .bodyB = arm, .localAnchorA = {-12, 5}, .localAnchorB = {0, 1},
                                   .enableLimit = true, .lowerAngle = -1.0f, .upperAngle = 1.0f, .enableMotor = true,
                                   .motorSpeed = 2.0f, .maxMotorTorque = 20.0f});
    // Prismatic with limit and motor: a slider on a tilted rail.
    const BodyId slider = box({-8, 3}, 0.3f);
    w.createJoint(PrismaticJointDef{.bodyA = ground, .bodyB = slider, .localAnchorA = {-8, 3}, .localAxisA = {0.8f, 0.6f},
                                    .enableLimit = true, .lower = -1.0f, .upper = 1.5f, .enableMotor = true,
                                    .motorSpeed = 1.0f, .maxMotorForce = 5.0f});
    // Distance spring with min/max length.
    const BodyId bob = box({-4, 2}, 0.25f);
    w.createJoint(DistanceJointDef{.bodyA = ground, .bodyB = bob, .localAnchorA = {-4, 6}, .length = 3.0f,
                                   .minLength = 1.0f, .maxLength = 4.0f, .hertz = 2.0f, .dampingRatio = 0.3f});
    // Soft weld: a box cantilevered from one that stands on the ground.
    const BodyId weldA = box({0, 0.5f}, 0.5f), weldB = box({1, 1.5f}, 0.5f);
    w.createJoint(WeldJointDef{.bodyA = weldA, .bodyB = weldB, .localAnchorA = {0.5f, 0.5f}, .localAnchorB = {-0.5f, -0.5f},
                               .hertz = 3.0f, .dampingRatio = 0.5f});
    // Wheel with motor on a chassis.
    const BodyId chassis = box({5, 2}, 0.5f);
    const BodyId wheel = w.createBody({.type = BodyType::Dynamic, .position = {5, 1}});
    w.createShape(wheel, {.friction = 0.9f}, Circle{{0, 0}, 0.4f});
    w.createJoint(WheelJointDef{.bodyA = chassis, .bodyB = wheel, .localAnchorA = {0, -1}, .enableMotor = true,
                                .motorSpeed = -3.0f, .maxMotorTorque = 10.0f});
    // Motor joint dragging a box towards an offset from the ground.
    const BodyId driven = box({9, 1}, 0.4f);
    w.createJoint(MotorJointDef{.bodyA = ground, .bodyB = driven, .linearOffset = {10, 2}, .angularOffset = 0.5f,
                                .maxForce = 50.0f, .maxTorque = 5.0f});
    // Mouse joint pulling a box up and sideways.
    const BodyId dragged = box({13, 1}, 0.4f);
    w.createJoint(MouseJointDef{.bodyA = ground, .bodyB = dragged, .target = {14, 3}, .maxForce = 200.0f});
    // A sensor zone over a small pile, a bullet shot into the pile, a ball left to sleep.
    const BodyId zone = w.createBody({.position = {20, 2}});
    w.createShape(zone, {.sensor = true}, makeBox(2, 2));
    for (int i = 0; i < 6; ++i) {
        const BodyId b = box({19.2f + 0.9f * static_cast<float>(i % 3), 0.5f + static_cast<float>(i / 3)}, 0.4f);
        w.setLinearVelocity(b, {0, -1});
    }
    const BodyId bullet = w.createBody({.type = BodyType::Dynamic, .position = {-25, 1}, .linearVelocity = {400, 0},
                                        .bullet = true});
    w.createShape(bullet, {.enableHitEvents = true}, Circle{{0, 0}, 0.05f});
    const BodyId wall = w.createBody({.position = {-20, 1}});
    w.createShape(wall, {}, makeBox(0.05f, 1));
    const BodyId ball = w.createBody({.type = BodyType::Dynamic, .position = {25, 0.5f}});
    w.createShape(ball, {}, Circle{{0, 0}, 0.5f});
    return w;
}

}  // namespace perpdot::test
