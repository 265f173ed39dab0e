// The contact rows solved four at a time. Constraints are graph-coloured (graph_color.hpp) so that
// the four lanes of a block never share a dynamic body; each block gathers its bodies' state
// into lanes, runs the rows of contact_solver_wide.hpp once for all four, and scatters the
// velocities back. Constraints no colour could take (a body touching more than 16 others) are
// solved one by one with the same rows at F = float, after the blocks.
#include <array>

#include "core/world_impl.hpp"

namespace perpdot {

using simd::Float4;

namespace {

// The lanes of one float of four constraints.
template <class Field>
Float4 lanesOf(const std::array<const ContactRows<float>*, 4>& lanes, Field field) {
    float x[4];
    for (int i = 0; i < 4; ++i) x[i] = field(*lanes[i]);
    return Float4::load(x);
}

}  // namespace

ContactRows<Float4> packContactRows(const std::array<const ContactRows<float>*, 4>& lanes) {
    using C = ContactRows<float>;
    ContactRows<Float4> r;
    r.invMassA = lanesOf(lanes, [](const C& c) { return c.invMassA; });
    r.invIA = lanesOf(lanes, [](const C& c) { return c.invIA; });
    r.invMassB = lanesOf(lanes, [](const C& c) { return c.invMassB; });
    r.invIB = lanesOf(lanes, [](const C& c) { return c.invIB; });
    r.normal.x = lanesOf(lanes, [](const C& c) { return c.normal.x; });
    r.normal.y = lanesOf(lanes, [](const C& c) { return c.normal.y; });
    r.friction = lanesOf(lanes, [](const C& c) { return c.friction; });
    r.rollingResistance = lanesOf(lanes, [](const C& c) { return c.rollingResistance; });
    r.tangentSpeed = lanesOf(lanes, [](const C& c) { return c.tangentSpeed; });
    r.rollingMass = lanesOf(lanes, [](const C& c) { return c.rollingMass; });
    r.rollingImpulse = lanesOf(lanes, [](const C& c) { return c.rollingImpulse; });
    r.biasRate = lanesOf(lanes, [](const C& c) { return c.biasRate; });
    r.massScale = lanesOf(lanes, [](const C& c) { return c.massScale; });
    r.impulseScale = lanesOf(lanes, [](const C& c) { return c.impulseScale; });
    for (int i = 0; i < 2; ++i) {
        ContactPointRows<Float4>& p = r.points[i];
        p.anchorA.x = lanesOf(lanes, [i](const C& c) { return c.points[i].anchorA.x; });
        p.anchorA.y = lanesOf(lanes, [i](const C& c) { return c.points[i].anchorA.y; });
        p.anchorB.x = lanesOf(lanes, [i](const C& c) { return c.points[i].anchorB.x; });
        p.anchorB.y = lanesOf(lanes, [i](const C& c) { return c.points[i].anchorB.y; });
        p.baseSeparation = lanesOf(lanes, [i](const C& c) { return c.points[i].baseSeparation; });
        p.normalImpulse = lanesOf(lanes, [i](const C& c) { return c.points[i].normalImpulse; });
        p.tangentImpulse = lanesOf(lanes, [i](const C& c) { return c.points[i].tangentImpulse; });
        p.maxNormalImpulse = lanesOf(lanes, [i](const C& c) { return c.points[i].maxNormalImpulse; });
        p.normalMass = lanesOf(lanes, [i](const C& c) { return c.points[i].normalMass; });
        p.tangentMass = lanesOf(lanes, [i](const C& c) { return c.points[i].tangentMass; });
        const bool active[4] = {lanes[0]->points[i].active, lanes[1]->points[i].active, lanes[2]->points[i].active,
                                lanes[3]->points[i].active};
        p.active = simd::maskFromBools(active);
    }
    return r;
}

namespace {

// Run `rows(blockRows, a, b)` on every block, then `rows(constraint, a, b)` on every overflow constraint.
template <class Rows>
void forEachContact(World::Impl& w, std::vector<BodyState>& states, Rows rows) {
    for (ContactBlock& block : w.contactBlocks) {
        BodyLanes<Float4> a = gatherBodies(states, block.bodyA);
        BodyLanes<Float4> b = gatherBodies(states, block.bodyB);
        rows(block.rows, a, b);
        scatterVelocities(states, block.bodyA, a);
        scatterVelocities(states, block.bodyB, b);
    }
    for (int index : w.overflowConstraints) {
        ContactConstraint& c = w.constraints[index];
        rows(c, states[c.indexA], states[c.indexB]);
    }
}

}  // namespace

// Colour the constraints in order, then lay them out colour by colour (Box2D v3's solve order:
// it keeps stacks as stiff as the plain constraint order does), four to a block; overflow last.
void prepareContactBlocks(World::Impl& w) {
    constexpr int overflow = GraphColoring::overflow;
    const int count = static_cast<int>(w.constraints.size());
    w.contactColoring.reset(static_cast<int>(w.states.size()));
    w.contactColors.resize(w.constraints.size());
    for (int index = 0; index < count; ++index) {
        const ContactConstraint& c = w.constraints[index];
        w.contactColors[index] = w.contactColoring.assign(c.indexA, c.indexB);
    }
    const ColorStarts start = sortByColor(w.contactColors, w.contactOrder);

    w.contactBlocks.clear();
    for (int color = 0; color < overflow; ++color) {
        for (int k = start[color]; k < start[color + 1]; ++k) {
            const int lane = (k - start[color]) % 4;
            if (lane == 0) w.contactBlocks.emplace_back();
            ContactBlock& block = w.contactBlocks.back();
            const ContactConstraint& c = w.constraints[w.contactOrder[k]];
            block.constraint[lane] = w.contactOrder[k];
            block.bodyA[lane] = c.indexA;
            block.bodyB[lane] = c.indexB;
        }
    }
    w.overflowConstraints.assign(w.contactOrder.begin() + start[overflow], w.contactOrder.end());
    static const ContactRows<float> emptyLane;  // no mass, no active point: leaves the bodies alone
    for (ContactBlock& block : w.contactBlocks) {
        std::array<const ContactRows<float>*, 4> lanes;
        for (int i = 0; i < 4; ++i) lanes[i] = block.constraint[i] < 0 ? &emptyLane : &w.constraints[block.constraint[i]];
        block.rows = packContactRows(lanes);
    }
}

void warmStartContacts(World::Impl& w, const StepContext& ctx) {
    forEachContact(w, *ctx.states, [](auto& c, auto& a, auto& b) { warmStartContact(c, a, b); });
}

void solveContacts(World::Impl& w, const StepContext& ctx, bool useBias) {
    forEachContact(w, *ctx.states, [&](auto& c, auto& a, auto& b) { solveContact(c, a, b, ctx, useBias); });
}

void unpackContactBlocks(World::Impl& w) {
    for (const ContactBlock& block : w.contactBlocks) {
        float rolling[4], normal[2][4], tangent[2][4], maxNormal[2][4];
        block.rows.rollingImpulse.store(rolling);
        for (int i = 0; i < 2; ++i) {
            block.rows.points[i].normalImpulse.store(normal[i]);
            block.rows.points[i].tangentImpulse.store(tangent[i]);
            block.rows.points[i].maxNormalImpulse.store(maxNormal[i]);
        }
        for (int lane = 0; lane < 4; ++lane) {
            if (block.constraint[lane] < 0) continue;
            ContactConstraint& c = w.constraints[block.constraint[lane]];
            c.rollingImpulse = rolling[lane];
            for (int i = 0; i < c.pointCount; ++i) {
                c.points[i].normalImpulse = normal[i][lane];
                c.points[i].tangentImpulse = tangent[i][lane];
                c.points[i].maxNormalImpulse = maxNormal[i][lane];
            }
        }
    }
}

}  // namespace perpdot
