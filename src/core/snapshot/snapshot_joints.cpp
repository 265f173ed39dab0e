// The joint store in a snapshot: each joint's common part through its field list
// (snapshot_fields.hpp), then its type's data through the type's kind (joint_type.hpp: the list in
// the type's file; format 1 held the data as the struct's raw bytes, which the kind reads too). Links are rebuilt from each body's saved joint list, and
// per-step values are left for prepareJoints to recompute.
#include <string>
#include <utility>

#include "core/joints/joint_store.hpp"
#include "core/snapshot/snapshot.hpp"
#include "core/snapshot/snapshot_fields.hpp"

namespace perpdot {

void writeJoints(ByteWriter& out, const JointStore& s, const Pool<Body>& bodies) {
    out.f32(s.invHs);
    out.u32(static_cast<uint32_t>(s.joints.capacity()));
    for (const Joint& j : s.joints.slots()) {
        out.u32(j.generation);
        out.boolean(j.alive);
        if (!j.alive) continue;
        writeFields(out, j);
        kindOf(j.type)->write(out, j.data);
    }
    out.u32(static_cast<uint32_t>(s.joints.freeList().size()));
    for (int i : s.joints.freeList()) out.i32(i);
    // Each body's joint list, head first (the order decides who is visited first).
    for (int body = 0; body < bodies.capacity(); ++body) {
        const std::vector<int> keys = s.bodyLists.keys(s.joints, body);
        out.u32(static_cast<uint32_t>(keys.size()));
        for (int e : keys) out.i32(e);
    }
}

void readJoints(ByteReader& in, JointStore& s, const Pool<Body>& bodies) {
    s.invHs = in.f32();
    const int count = in.count(5, "joint");
    const int bodyCount = bodies.capacity();
    s.joints.restoreSlots(count);
    std::vector<bool> alive(count);
    for (int index = 0; index < count; ++index) {
        Joint& j = s.joints[index];
        j.generation = in.u32();
        j.alive = alive[index] = in.boolean();
        if (!j.alive) continue;
        readFields(in, j);
        if (j.bodyA < 0 || j.bodyA >= bodyCount || j.bodyB < 0 || j.bodyB >= bodyCount || j.bodyA == j.bodyB ||
            !bodies[j.bodyA].alive || !bodies[j.bodyB].alive)
            in.fail("joint " + std::to_string(index) + " needs two different live bodies");
        const JointKind* kind = kindOf(j.type);
        if (!kind) in.fail("joint type " + std::to_string(static_cast<int>(j.type)) + " is unknown");
        kind->read(in, j.data);
    }
    std::vector<int> free(in.count(4, "free joint"));
    std::vector<bool> listed(count, false);
    for (int& i : free) {
        i = in.integer(0, count - 1, "free joint");
        if (alive[i] || listed[i]) in.fail("free joint list names a live or repeated slot");
        listed[i] = true;
    }
    int dead = 0;
    for (bool a : alive) dead += a ? 0 : 1;
    if (dead != static_cast<int>(free.size())) in.fail("free joint list misses dead slots");
    s.joints.restoreFreeList(std::move(free));

    std::vector<bool> seen(2 * static_cast<size_t>(count), false);
    for (int body = 0; body < bodyCount; ++body) {
        const int n = in.count(4, "joint edge");
        if (n != bodies[body].jointCount) in.fail("body " + std::to_string(body) + " joint count does not match its joints");
        std::vector<int> keys(n);
        for (int& e : keys) {
            e = in.integer(0, 2 * count - 1, "joint edge");
            const Joint& j = s.joints[e >> 1];
            if (!j.alive || seen[e] || ((e & 1) ? j.bodyB : j.bodyA) != body) in.fail("joint list is inconsistent");
            seen[e] = true;
        }
        s.bodyLists.restore(s.joints, body, keys);
    }
    for (int index = 0; index < count; ++index)
        if (alive[index] && !(seen[2 * index] && seen[2 * index + 1])) in.fail("joint missing from a body's list");
}

}  // namespace perpdot
