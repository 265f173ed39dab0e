// The joint store in a snapshot: each joint's common part and its type's data through their field
// lists (snapshot_fields.hpp); format 1 held the type data as the struct's raw bytes, which
// readLayoutV1 walks with the same list. Links are rebuilt from each body's saved joint list, and
// per-step values are left for prepareJoints to recompute.
#include <memory>
#include <string>

#include "core/joint_store.hpp"
#include "core/snapshot.hpp"
#include "core/snapshot_fields.hpp"

namespace perpdot {

void writeJoints(ByteWriter& out, const World::Impl& w) {
    const JointStore& s = *w.joints;
    out.f32(s.invHs);
    out.u32(static_cast<uint32_t>(s.joints.size()));
    for (const Joint& j : s.joints) {
        out.u32(j.generation);
        out.boolean(j.alive);
        if (!j.alive) continue;
        writeFields(out, j);
        visitJointData(j.type, j.data, [&](const auto& data) { writeFields(out, data); });
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
        readFields(in, j);
        if (j.bodyA < 0 || j.bodyA >= bodyCount || j.bodyB < 0 || j.bodyB >= bodyCount || j.bodyA == j.bodyB ||
            !w.bodies[j.bodyA].alive || !w.bodies[j.bodyB].alive)
            in.fail("joint " + std::to_string(index) + " needs two different live bodies");
        const bool known = visitJointData(j.type, j.data, [&](auto& data) {
            std::construct_at(&data);  // the live member, value-initialised as createJoint does
            if (in.version == 1) {
                size_t offset = 0;
                readLayoutV1(in, data, offset);
            } else {
                readFields(in, data);
            }
        });
        if (!known) in.fail("joint type " + std::to_string(static_cast<int>(j.type)) + " is unknown");
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
