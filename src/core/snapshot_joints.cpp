// The joint store in a snapshot. A Joint is plain data: the common part is written field by
// field, the type's member of JointData as its bytes (zero-initialised when the joint was made,
// so they are deterministic). On reading, the booleans inside those bytes are checked (any other
// byte value would be undefined behaviour to read), links are rebuilt from each body's saved
// joint list, and per-step values are left for prepareJoints to recompute.
#include <cstddef>
#include <cstring>
#include <string>

#include "core/joint_store.hpp"
#include "core/snapshot.hpp"

namespace perpdot {

namespace {

// Size of the live member of JointData, and the offsets of its bool members.
struct MemberLayout {
    size_t size;
    size_t bools[2];
    int boolCount;
};

MemberLayout layoutOf(JointType type) {
    switch (type) {
        case JointType::Revolute:
            return {sizeof(RevoluteJoint), {offsetof(RevoluteJoint, enableLimit), offsetof(RevoluteJoint, enableMotor)}, 2};
        case JointType::Prismatic:
            return {sizeof(PrismaticJoint), {offsetof(PrismaticJoint, enableLimit), offsetof(PrismaticJoint, enableMotor)}, 2};
        case JointType::Distance: return {sizeof(DistanceJoint), {}, 0};
        case JointType::Weld: return {sizeof(WeldJoint), {}, 0};
        case JointType::Wheel: return {sizeof(WheelJoint), {offsetof(WheelJoint, enableMotor)}, 1};
        case JointType::Motor: return {sizeof(MotorJoint), {}, 0};
        case JointType::Mouse: return {sizeof(MouseJoint), {}, 0};
    }
    return {0, {}, 0};
}

}  // namespace

void writeJoints(ByteWriter& out, const World::Impl& w) {
    const JointStore& s = *w.joints;
    out.f32(s.invHs);
    out.u32(static_cast<uint32_t>(s.joints.size()));
    for (const Joint& j : s.joints) {
        out.u32(j.generation);
        out.boolean(j.alive);
        if (!j.alive) continue;
        out.u8(static_cast<uint8_t>(j.type));
        out.boolean(j.collideConnected);
        out.i32(j.bodyA);
        out.i32(j.bodyB);
        out.vec2(j.localAnchorA);
        out.vec2(j.localAnchorB);
        out.f32(j.referenceAngle);
        const MemberLayout layout = layoutOf(j.type);
        const auto* bytes = reinterpret_cast<const uint8_t*>(&j.data);
        for (size_t i = 0; i < layout.size; ++i) out.u8(bytes[i]);
    }
    out.u32(static_cast<uint32_t>(s.freeList.size()));
    for (int i : s.freeList) out.i32(i);
    // Each body's joint list, head first (the order decides who is visited first).
    for (size_t body = 0; body < w.bodies.size(); ++body) {
        std::vector<int> keys;
        for (int e = body < s.bodyHead.size() ? s.bodyHead[body] : -1; e >= 0; e = s.joints[e >> 1].edges[e & 1].next)
            keys.push_back(e);
        out.u32(static_cast<uint32_t>(keys.size()));
        for (int e : keys) out.i32(e);
    }
}

void readJoints(ByteReader& in, World::Impl& w) {
    JointStore& s = *w.joints;
    s.invHs = in.f32();
    const int count = in.count(5, "joint");
    const int bodyCount = static_cast<int>(w.bodies.size());
    s.joints.assign(count, Joint{});
    std::vector<bool> alive(count);
    for (int index = 0; index < count; ++index) {
        Joint& j = s.joints[index];
        j.generation = in.u32();
        j.alive = alive[index] = in.boolean();
        if (!j.alive) continue;
        const uint8_t type = in.u8();
        if (type > static_cast<uint8_t>(JointType::Mouse)) in.fail("joint type " + std::to_string(type) + " is unknown");
        j.type = static_cast<JointType>(type);
        j.collideConnected = in.boolean();
        j.bodyA = in.integer(0, bodyCount - 1, "joint body");
        j.bodyB = in.integer(0, bodyCount - 1, "joint body");
        if (j.bodyA == j.bodyB || !w.bodies[j.bodyA].alive || !w.bodies[j.bodyB].alive)
            in.fail("joint " + std::to_string(index) + " needs two different live bodies");
        j.localAnchorA = in.vec2();
        j.localAnchorB = in.vec2();
        j.referenceAngle = in.f32();
        const MemberLayout layout = layoutOf(j.type);
        uint8_t bytes[sizeof(JointData)] = {};
        for (size_t i = 0; i < layout.size; ++i) bytes[i] = in.u8();
        for (int b = 0; b < layout.boolCount; ++b)
            if (bytes[layout.bools[b]] > 1) in.fail("joint " + std::to_string(index) + " holds an invalid boolean");
        std::memcpy(static_cast<void*>(&j.data), bytes, sizeof(JointData));
    }
    s.freeList.assign(in.count(4, "free joint"), 0);
    std::vector<bool> listed(count, false);
    for (int& i : s.freeList) {
        i = in.integer(0, count - 1, "free joint");
        if (alive[i] || listed[i]) in.fail("free joint list names a live or repeated slot");
        listed[i] = true;
    }
    int dead = 0;
    for (bool a : alive) dead += a ? 0 : 1;
    if (dead != static_cast<int>(s.freeList.size())) in.fail("free joint list misses dead slots");

    s.bodyHead.assign(w.bodies.size(), -1);
    std::vector<bool> seen(2 * static_cast<size_t>(count), false);
    for (int body = 0; body < bodyCount; ++body) {
        const int n = in.count(4, "joint edge");
        if (n != w.bodies[body].jointCount) in.fail("body " + std::to_string(body) + " joint count does not match its joints");
        int prev = -1;
        for (int k = 0; k < n; ++k) {
            const int e = in.integer(0, 2 * count - 1, "joint edge");
            const Joint& j = s.joints[e >> 1];
            if (!j.alive || seen[e] || ((e & 1) ? j.bodyB : j.bodyA) != body) in.fail("joint list is inconsistent");
            seen[e] = true;
            s.joints[e >> 1].edges[e & 1] = {prev, -1};
            if (prev >= 0) s.joints[prev >> 1].edges[prev & 1].next = e;
            else s.bodyHead[body] = e;
            prev = e;
        }
    }
    for (int index = 0; index < count; ++index)
        if (alive[index] && !(seen[2 * index] && seen[2 * index + 1])) in.fail("joint missing from a body's list");
}

}  // namespace perpdot
