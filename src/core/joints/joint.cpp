// The joint store and the World's joint API: creation and destruction with generational ids,
// per-body joint lists (for collideConnected and destroyBody), and the solver stages, which
// dispatch to the joint types' stages (joint_registry.cpp), four joints of a type at a time where
// the type has lanes (joint_solver_wide.hpp).
#include <cmath>
#include <string>

#include "core/contacts/contact_world.hpp"
#include "core/joints/joint_prismatic.hpp"
#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_solver_wide.hpp"
#include "core/joints/joint_tree_stiffness.hpp"
#include "core/joints/joint_weld.hpp"
#include "core/solver/solver_world.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

void JointStoreDeleter::operator()(JointStore* store) const { delete store; }
JointStorePtr makeJointStore() { return JointStorePtr(new JointStore); }
void JointScratchDeleter::operator()(JointScratch* scratch) const { delete scratch; }
JointScratchPtr makeJointScratch() { return JointScratchPtr(new JointScratch); }

void requireFinite(bool ok, const char* what) {
    if (!ok) throw Error(std::string(what) + " must be finite");
}

namespace {

JointStore& store(World::Impl& w) { return *w.joints; }
const JointStore& store(const World::Impl& w) { return *w.joints; }
// The same parts through the solver's view, for the solver stages.
JointStore& store(const SolverWorld& w) { return w.joints; }
JointScratch& jointScratch(const SolverWorld& w) { return w.scratch.joints; }

// A joint that forbids collision between its bodies removes their contacts.
void destroyContactsBetween(World::Impl& w, int bodyA, int bodyB) {
    const ContactCache& cache = w.contactCache;
    cache.bodyLists.forEach(cache.contacts, bodyA, [&](int index, int) {
        const Contact& c = cache.contacts[index];
        if ((c.bodyA == bodyA && c.bodyB == bodyB) || (c.bodyA == bodyB && c.bodyB == bodyA)) destroyContact(contactWorld(w), index);
    });
}

JointReaction reactionOf(const Joint& j) { return stagesOf(j.type).reaction(j.data); }

}  // namespace

// The parts removing a joint touches (JointRemoval, joint.hpp).
JointRemoval jointRemoval(World::Impl& w) {
    return {.joints = *w.joints, .bodies = w.bodies, .shapes = w.shapes, .broadphase = w.broadphase};
}

void removeJoint(const JointRemoval& w, int index) {
    JointStore& s = w.joints;
    Joint& j = s.joints[index];
    s.bodyLists.unlink(s.joints, index, 0, j.bodyA);
    s.bodyLists.unlink(s.joints, index, 1, j.bodyB);
    Body& a = w.bodies[j.bodyA];
    Body& b = w.bodies[j.bodyB];
    --a.jointCount;
    --b.jointCount;
    wakeIsland(w.bodies, j.bodyA);
    wakeIsland(w.bodies, j.bodyB);
    // The broadphase skipped this pair while the joint forbade it: let it look again.
    if (!j.collideConnected)
        for (int shape : b.shapes)
            for (int proxy : w.shapes[shape].proxies) {
                w.broadphase.collision.requery(proxy);
                w.broadphase.movedProxies.push_back(proxy);
            }
    s.joints.destroy(index);
}

Joint& addJoint(World::Impl& w, JointType type, BodyId bodyA, BodyId bodyB, Vec2 localAnchorA, Vec2 localAnchorB,
                float referenceAngle, bool collideConnected, void* userData) {
    checkUnlocked(w.locked, "createJoint");
    w.body(bodyA, "createJoint");
    w.body(bodyB, "createJoint");
    if (bodyA.index == bodyB.index) throw Error("a joint needs two different bodies");
    requireFinite(isFinite(localAnchorA) && isFinite(localAnchorB), "joint anchors");
    requireFinite(std::isfinite(referenceAngle), "referenceAngle");

    JointStore& s = store(w);
    const int index = s.joints.create();
    Joint& j = s.joints[index];
    j.type = type;
    j.bodyA = bodyA.index;
    j.bodyB = bodyB.index;
    j.localAnchorA = localAnchorA;
    j.localAnchorB = localAnchorB;
    j.referenceAngle = referenceAngle;
    j.collideConnected = collideConnected;
    j.userData = userData;
    s.bodyLists.link(s.joints, index, 0, j.bodyA);
    s.bodyLists.link(s.joints, index, 1, j.bodyB);
    ++w.bodies[j.bodyA].jointCount;
    ++w.bodies[j.bodyB].jointCount;
    if (!collideConnected) destroyContactsBetween(w, j.bodyA, j.bodyB);
    wakeIsland(w.bodies, j.bodyA);
    wakeIsland(w.bodies, j.bodyB);
    return j;
}

Joint& checkedJoint(const World::Impl& w, JointId id, const char* call) {
    return const_cast<Joint&>(checkedItem(store(w).joints, id, w.identity, "JointId", call));
}

JointId jointId(const World::Impl& w, const Joint& joint) {
    return {static_cast<int32_t>(&joint - store(w).joints.slots().data()), joint.generation, w.identity.issued};
}

const Body& checkedBody(const World::Impl& w, BodyId id, const char* call) { return w.body(id, call); }
const Body& bodyAt(const World::Impl& w, int index) { return w.bodies[index]; }
BodyId bodyIdAt(const World::Impl& w, int index) { return w.bodyId(index); }

JointWorld jointWorld(World::Impl& w) { return {.joints = *w.joints, .bodies = w.bodies, .locked = w.locked}; }

// --- Solver stages ---

namespace {

// The frame at step start and a working copy of the type data, then the type's own prepare.
void prepareJoint(PreparedJoint& j, const SolverWorld& w, const Joint& joint, const StepContext& ctx) {
    const Body& a = w.bodies[joint.bodyA];
    const Body& b = w.bodies[joint.bodyB];
    j.type = joint.type;
    j.data = joint.data;
    j.indexA = w.scratch.bodies.bodySlots[joint.bodyA];
    j.indexB = w.scratch.bodies.bodySlots[joint.bodyB];
    // A body outside the solver (static, or held asleep) is immovable for this step.
    j.mass = {j.indexA ? a.invMass : 0.0f, j.indexA ? a.invInertia : 0.0f, j.indexB ? b.invMass : 0.0f,
              j.indexB ? b.invInertia : 0.0f};
    j.anchorA = rotate(a.xf.q, joint.localAnchorA - a.localCenter);
    j.anchorB = rotate(b.xf.q, joint.localAnchorB - b.localCenter);
    j.deltaCenter = b.center - a.center;
    j.deltaAngle = b.angle - a.angle - joint.referenceAngle;
    j.breakable = !std::isinf(joint.breakForce) || !std::isinf(joint.breakTorque);
    stagesOf(j.type).prepare(j, ctx, a, b);
}

// Joints a tree may take (joint_tree.hpp): unbreakable revolute and prismatic joints, and welds
// that do not bend (a spring weld's angle row is soft).
bool treeJoint(const PreparedJoint& j) {
    if (j.breakable) return false;
    return j.type == JointType::Revolute || j.type == JointType::Prismatic ||
           (j.type == JointType::Weld && j.data.as<WeldJoint>().hertz == 0.0f);
}

// What colorJoints reads of a prepared joint (JointKey); a side moves where it has mass or inertia.
JointKey keyOf(const PreparedJoint& j) {
    const JointLaneStages* lanes = stagesOf(j.type).lanes;
    return {j.indexA,
            j.indexB,
            j.type,
            j.mass.mA != 0.0f || j.mass.iA != 0.0f,
            j.mass.mB != 0.0f || j.mass.iB != 0.0f,
            treeJoint(j),
            (j.type == JointType::Revolute && j.data.as<RevoluteJoint>().enableLimit) ||
                (j.type == JointType::Prismatic && j.data.as<PrismaticJoint>().enableLimit),
            lanes != nullptr && lanes->optionalRows(j)};
}

// Units [begin, end) of colour `color`: its blocks, then its other joints; `wide(stages, blocks,
// count)` on a run of blocks of one type and `scalar(joint, pair)` on a joint. Joints of one
// colour share no moving body, so their order within it is free and workers may run its units
// side by side.
template <class Wide, class Scalar>
void forJointUnits(JointScratch& d, SolverBodies& bodies, int color, int begin, int end, Wide wide, Scalar scalar) {
    std::vector<BodyState>& states = bodies.states;
    const int blocks = d.blockStart[color + 1] - d.blockStart[color];
    JointBlock* colorBlocks = d.blocks.data() + d.blockStart[color];
    for (int unit = begin, last = std::min(end, blocks); unit < last;) {
        const JointBlock& block = colorBlocks[unit];
        const int run = std::min(last, block.head.typeEnd - d.blockStart[color]);
        wide(*stagesOf(block.head.type).lanes, colorBlocks + unit, run - unit);
        unit = run;
    }
    // The static slot 0 is shared by the colour's joints: each run writes (nothing) to its own copy.
    BodyState fixed = states[0];
    for (int unit = std::max(begin, blocks); unit < end; ++unit) {
        PreparedJoint& j = d.prepared[d.scalarOrder[d.scalarStart[color] + unit - blocks]];
        JointPair p = pairOf(j.indexA == 0 ? fixed : states[j.indexA], j.indexB == 0 ? fixed : states[j.indexB],
                             bodies.stepRotation, j);
        scalar(j, p);
    }
}

}  // namespace

void jointRows(JointScratch& d, SolverBodies& bodies, const StepContext& ctx, RowPass pass, int color, int begin, int end) {
    std::vector<BodyState>& states = bodies.states;
    if (pass == RowPass::WarmStart) {
        forJointUnits(
            d, bodies, color, begin, end,
            [&](const JointLaneStages& lanes, JointBlock* blocks, int count) { lanes.warmStart(blocks, count, states); },
            [](PreparedJoint& j, JointPair& p) { stagesOf(j.type).warmStart(j, p); });
        return;
    }
    const bool useBias = pass == RowPass::Solve;
    const std::vector<float>& stepRotation = bodies.stepRotation;
    forJointUnits(
        d, bodies, color, begin, end,
        [&](const JointLaneStages& lanes, JointBlock* blocks, int count) {
            lanes.solve(blocks, count, states, stepRotation, ctx, useBias);
        },
        [&](PreparedJoint& j, JointPair& p) {
            const JointStages& stages = stagesOf(j.type);
            stages.solve(j, p, ctx, useBias);
            // The relax pass is a substep's last word on a joint: its λ is what the substep applied.
            if (pass == RowPass::Relax && j.breakable) {
                JointReaction& sum = d.stepImpulse[static_cast<size_t>(&j - d.prepared.data())];
                const JointReaction substep = stages.reaction(j.data);
                sum.linear += substep.linear;
                sum.angular += substep.angular;
            }
        });
}

namespace {

// The joints of a type with lanes go to the blocks, unless no colour could take them or they have
// break limits (their impulses are summed one joint at a time): -1 alone, 0
// in lanes with the type's rows alone, 1 with optional rows (JointScratch::laneRows).
int8_t laneRowsOf(int color, const JointKey& j, bool breakable) {
    if (color == GraphColoring::overflow || stagesOf(j.type).lanes == nullptr || breakable) return -1;
    return j.optionalRows ? 1 : 0;
}

}  // namespace

// Store order, the order of the joints' and bodies' memory, throughout. The workers select the
// awake joints and prepare them.
void prepareJoints(const SolverWorld& w, const StepContext& ctx) {
    JointStore& s = store(w);
    JointScratch& d = jointScratch(w);
    s.invHs = ctx.invHs;
    auto awake = [&](int index) {
        const Joint& joint = s.joints[index];
        return joint.alive && (w.scratch.bodies.bodySlots[joint.bodyA] != 0 || w.scratch.bodies.bodySlots[joint.bodyB] != 0) &&
               w.bodies[joint.bodyA].enabled && w.bodies[joint.bodyB].enabled;  // World::setEnabled
    };
    // prepareJoint writes every field, so last step's elements are reused as they are.
    w.workers.parallelSelect(
        s.joints.capacity(), awake,
        [&](int total) {
            d.awake.resize(total);
            d.prepared.resize(total);
            d.keys.resize(total);
            d.stepImpulse.assign(total, {});
            d.direct.assign(total, 0);
        },
        [&](int k, int index) {
            d.awake[k] = index;
            prepareJoint(d.prepared[k], w, s.joints[index], ctx);
            d.keys[k] = keyOf(d.prepared[k]);
        });
}

// One by one, the prepared joints are coloured (graph_color.hpp: joints of one colour share no
// moving body, so a pass never waits for the velocities the previous joint wrote, and four of a
// type can share SIMD lanes), the joint trees leave the colours, and each joint is sent to the
// next lane of its colour and type or to its colour's next scalar slot (within a colour the order
// is free); the workers pack the blocks' lanes.
void colorJoints(const SolverWorld& w, const StepContext& ctx) {
    constexpr int overflow = GraphColoring::overflow;
    JointScratch& d = jointScratch(w);
    const int count = static_cast<int>(d.keys.size());
    d.colors.resize(d.keys.size());
    d.laneRows.resize(d.keys.size());
    // One colouring for joints and contacts (the constraint graph): joints first, contacts then
    // take the colours their bodies' joints left (prepareContactBlocks).
    GraphColoring& coloring = w.scratch.coloring;
    coloring.reset(static_cast<int>(w.scratch.bodies.states.size()));
    // Joints of joint trees take no colour: they are solved directly (joint_tree.hpp).
    findJointTrees(d.trees, d.keys, w.scratch.bodies.states);
    stiffenJointTrees(d.trees, d.prepared, ctx.hs, static_cast<int>(w.scratch.bodies.states.size()));
    // Lanes by colour and type: those of joints with the type's rows alone, and of joints with
    // optional rows (a motor, a limit).
    constexpr int types = jointTypeCount;
    std::array<std::array<int, types>, overflow + 1> plainLanes{}, optionalLanes{};
    std::array<int, overflow + 1> scalarCount{};
    for (int k = 0; k < count; ++k) {
        if (d.trees.inTree[k] || d.direct[k]) continue;
        const JointKey& j = d.keys[k];
        const int color = d.colors[k] = coloring.assign(j.indexA, j.indexB);
        const int8_t rows = d.laneRows[k] = laneRowsOf(color, j, d.prepared[k].breakable);
        if (rows < 0) ++scalarCount[color];
        else ++(rows > 0 ? optionalLanes : plainLanes)[color][static_cast<int>(j.type)];
    }

    // A colour's blocks by type; within a type the joints with its rows alone take the first
    // lanes and those with optional rows the lanes after them, so that at most one block of the
    // colour and type solves optional rows in lanes that have none.
    std::array<std::array<int, types>, overflow + 1> nextPlain{}, nextOptional{}, typeEnd{};
    for (int color = 0; color <= overflow; ++color) {
        int block = d.blockStart[color];
        for (int type = 0; type < types; ++type) {
            nextPlain[color][type] = 4 * block;
            nextOptional[color][type] = 4 * block + plainLanes[color][type];
            block += (plainLanes[color][type] + optionalLanes[color][type] + 3) / 4;
            typeEnd[color][type] = block;
        }
        d.blockStart[color + 1] = block;
        d.scalarStart[color + 1] = d.scalarStart[color] + scalarCount[color];
    }
    const int blocks = d.blockStart[overflow + 1];
    d.blocks.resize(blocks);
    d.blockLanes.assign(blocks, {-1, -1, -1, -1});
    d.scalarOrder.resize(d.scalarStart[overflow + 1]);
    ColorStarts nextScalar = d.scalarStart;
    for (int k = 0; k < count; ++k) {
        const int color = d.colors[k];
        if (d.trees.inTree[k] || d.direct[k]) continue;
        if (d.laneRows[k] < 0) {
            d.scalarOrder[nextScalar[color]++] = k;
            continue;
        }
        const int type = static_cast<int>(d.keys[k].type);
        const int lane = d.laneRows[k] > 0 ? nextOptional[color][type]++ : nextPlain[color][type]++;
        d.blockLanes[lane / 4][lane % 4] = k;
        d.blocks[lane / 4].head.typeEnd = typeEnd[color][type];
    }
    w.workers.parallelFor(blocks, 16, [&](int begin, int end, int) {
        for (int block = begin; block < end; ++block) {
            std::array<const PreparedJoint*, 4> lanes;
            std::array<int, 4> joints;
            bool optionalRows = false;
            const std::array<int, 4>& ks = d.blockLanes[block];
            for (int lane = 0; lane < 4; ++lane) {
                const int k = ks[lane] < 0 ? ks[0] : ks[lane];  // an empty lane: the first joint's rows
                lanes[lane] = &d.prepared[k];
                joints[lane] = ks[lane] < 0 ? -1 : d.awake[k];
                optionalRows = optionalRows || d.laneRows[k] > 0;
            }
            packJointBlock(d.blocks[block], lanes, joints, optionalRows);
        }
    });
}

// Every substep begins by re-applying the accumulated impulses (Box2D v3's soft step).
int jointUnitCount(const JointScratch& d, int color) {
    return d.blockStart[color + 1] - d.blockStart[color] + d.scalarStart[color + 1] - d.scalarStart[color];
}

int serialJointCount(const JointScratch& d) {
    return jointUnitCount(d, GraphColoring::overflow) + static_cast<int>(d.trees.joints.size());
}

void serialJointRows(JointScratch& d, SolverBodies& bodies, const StepContext& ctx, RowPass pass) {
    constexpr int overflow = GraphColoring::overflow;
    jointRows(d, bodies, ctx, pass, overflow, 0, jointUnitCount(d, overflow));
    if (pass == RowPass::WarmStart)
        warmStartJointTrees(bodies, d.trees, d.prepared);
    else
        solveJointTrees(bodies, d.trees, d.prepared, ctx, pass == RowPass::Solve);
}

void projectJoints(JointScratch& d, SolverBodies& bodies) {
    projectJointTrees(bodies, d.trees, d.prepared);
}

// The accumulated impulses go back to the joints, ready for the next step's warm start.
void storeJointImpulses(const SolverWorld& w, const StepContext&) {
    JointStore& s = store(w);
    JointScratch& d = jointScratch(w);
    w.workers.parallelFor(static_cast<int>(d.blocks.size()), 64, [&](int begin, int end, int) {
        for (int block = begin; block < end; ++block) stagesOf(d.blocks[block].head.type).lanes->store(d.blocks[block], s.joints.slots());
    });
    for (int position : d.scalarOrder) s.joints[d.awake[position]].data = d.prepared[position].data;
    for (int position : d.trees.joints) s.joints[d.awake[position]].data = d.prepared[position].data;
    for (int k = 0; k < static_cast<int>(d.direct.size()); ++k)
        if (d.direct[k]) s.joints[d.awake[k]].data = d.prepared[k].data;
}

bool jointAllowsCollision(const Pool<Body>& bodies, const JointStore& s, int bodyA, int bodyB) {
    if (bodies[bodyA].jointCount == 0 || bodies[bodyB].jointCount == 0) return true;
    if (bodies[bodyB].jointCount < bodies[bodyA].jointCount) std::swap(bodyA, bodyB);
    for (int key = s.bodyLists.head(bodyA); key >= 0; key = EdgeList::next(s.joints, key)) {
        const Joint& j = s.joints[key >> 1];
        const int other = (key & 1) ? j.bodyA : j.bodyB;
        if (other == bodyB && !j.collideConnected) return false;
    }
    return true;
}

std::vector<std::pair<JointId, void*>> destroyJointsOf(World::Impl& w, int body) {
    JointStore& s = store(w);
    std::vector<std::pair<JointId, void*>> goodbyes;
    while (s.bodyLists.head(body) >= 0) {
        const int index = s.bodyLists.head(body) >> 1;
        if (w.jointDestroyed) goodbyes.emplace_back(jointId(w, s.joints[index]), s.joints[index].userData);
        removeJoint(jointRemoval(w), index);
    }
    return goodbyes;
}

void forEachJointPair(const JointStore& s, void (*visit)(void* context, int bodyA, int bodyB), void* context) {
    s.joints.forEachLive([&](int, const Joint& j) { visit(context, j.bodyA, j.bodyB); });
}

// --- World API ---

void World::destroyJoint(JointId id) {
    checkUnlocked(impl_->locked, "destroyJoint");
    checkedJoint(*impl_, id);
    removeJoint(jointRemoval(*impl_), id.index);
}

bool World::isValid(JointId id) const {
    return isLiveHandle(store(*impl_).joints, id, impl_->identity);
}

std::vector<JointId> World::joints() const {
    std::vector<JointId> ids;
    store(*impl_).joints.forEachLive([&](int i, const Joint& j) { ids.push_back({i, j.generation, impl_->identity.issued}); });
    return ids;
}

JointType World::jointType(JointId id) const { return checkedJoint(*impl_, id).type; }
BodyId World::jointBodyA(JointId id) const { return impl_->bodyId(checkedJoint(*impl_, id).bodyA); }
BodyId World::jointBodyB(JointId id) const { return impl_->bodyId(checkedJoint(*impl_, id).bodyB); }

Vec2 World::jointAnchorA(JointId id) const {
    const Joint& j = checkedJoint(*impl_, id);
    return transformPoint(impl_->bodies[j.bodyA].xf, j.localAnchorA);
}

Vec2 World::jointAnchorB(JointId id) const {
    const Joint& j = checkedJoint(*impl_, id);
    return transformPoint(impl_->bodies[j.bodyB].xf, j.localAnchorB);
}

// The accumulated impulse is what every substep applies, so force = λ / hs (Box2D v3).
Vec2 World::jointReactionForce(JointId id) const {
    return store(*impl_).invHs * reactionOf(checkedJoint(*impl_, id)).linear;
}

float World::jointReactionTorque(JointId id) const {
    return store(*impl_).invHs * reactionOf(checkedJoint(*impl_, id)).angular;
}

void World::setJointBreakLimits(JointId id, float maxForce, float maxTorque, bool destroy) {
    checkUnlocked(impl_->locked, "setJointBreakLimits");
    Joint& j = checkedJoint(*impl_, id);
    if (!(maxForce >= 0.0f)) throw Error("setJointBreakLimits: maxForce must be >= 0 (infinity: never breaks)");
    if (!(maxTorque >= 0.0f)) throw Error("setJointBreakLimits: maxTorque must be >= 0 (infinity: never breaks)");
    j.breakForce = maxForce;
    j.breakTorque = maxTorque;
    j.destroyOnBreak = destroy;
}

// A joint breaks when |F| > breakForce or |τ| > breakTorque, F and τ its reaction on B averaged
// over the step: the impulses of all its substeps summed (JointScratch::stepImpulse) over h, so a
// blow within one substep counts in full. Asleep joints were not solved and do not break.
void breakJoints(const JointRemoval& w, JointScratch& d, EventBuffers& events, const WorldIdentity& identity,
                 Workers& workers, const StepContext& ctx) {
    const JointStore& s = w.joints;
    auto reaction = [&](int k) {
        const JointReaction& r = d.stepImpulse[k];
        return std::pair{ctx.invH * r.linear, ctx.invH * r.angular};  // force, torque
    };
    auto overLimit = [&](int k) {
        if (!d.prepared[k].breakable) return false;
        const Joint& j = s.joints[d.awake[k]];
        const auto [force, torque] = reaction(k);
        return length(force) > j.breakForce || std::fabs(torque) > j.breakTorque;
    };
    // The workers find the joints over their limits; a break wakes bodies, so which of them are
    // awake is asked one by one, in store order, as the joints break.
    workers.parallelSelect(
        static_cast<int>(d.awake.size()), overLimit, [&](int total) { d.breaking.resize(total); },
        [&](int k, int prepared) { d.breaking[k] = prepared; });
    for (int k : d.breaking) {
        const int index = d.awake[k];
        const Joint& j = s.joints[index];
        if (!w.bodies[j.bodyA].awake && !w.bodies[j.bodyB].awake) continue;  // asleep: nothing changed
        const auto [force, torque] = reaction(k);
        events.jointBreak.push_back({handleAt<JointId>(s.joints, index, identity), force, torque, j.destroyOnBreak, j.userData});
        if (j.destroyOnBreak) removeJoint(w, index);
    }
}

void World::setMouseTarget(JointId id, Vec2 target) {
    checkUnlocked(impl_->locked, "setMouseTarget");
    Joint& j = checkedJoint(*impl_, id);
    if (j.type != JointType::Mouse) throw Error("setMouseTarget: not a mouse joint");
    requireFinite(isFinite(target), "setMouseTarget: target");
    j.localAnchorA = invTransformPoint(impl_->bodies[j.bodyA].xf, target);
    wakeIsland(impl_->bodies, j.bodyB);
}

void World::setMotorSpeed(JointId id, float speed) {
    checkUnlocked(impl_->locked, "setMotorSpeed");
    Joint& j = checkedJoint(*impl_, id);
    requireFinite(std::isfinite(speed), "setMotorSpeed: speed");
    float* (*motorSpeed)(JointData&) = kindOf(j.type)->motorSpeed;
    if (!motorSpeed) throw Error("setMotorSpeed: the joint's type has no motor");
    *motorSpeed(j.data) = speed;
    wakeIsland(impl_->bodies, j.bodyA);
    wakeIsland(impl_->bodies, j.bodyB);
}

}  // namespace perpdot
