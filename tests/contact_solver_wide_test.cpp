// The contact rows of src/core/solver/contact_solver_wide.hpp solve four constraints in simd::Float4
// lanes with bit for bit the results of solving them one at a time with F = float (no FMA, no
// approximate reciprocal), including one-point manifolds, rolling resistance, restitution (the pass
// after the substeps, which skips slow, non-pushing and inelastic points) and empty lanes, the lanes
// taking only the rows their block uses (RowUses) and the scalar solves all of them; and so does
// the derivation of the prepared rows from a contact's gathered values.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <vector>

#include "core/solver/contact_solver_wide.hpp"
#include "lanes_helpers.hpp"

namespace perpdot {
namespace {

using lanes_test::Random;
using lanes_test::randomBody;
using lanes_test::sameBits;

// What the rows of a round use, beyond the fields every pass reads.
struct Kinds {
    bool flat = false, conveyor = true, elastic = true;
};

ContactRows<float> randomRows(Random& r, int pointCount, bool rolling, Kinds kinds = {}) {
    ContactRows<float> c;
    c.invIA = r(0.1f, 4.0f);
    c.invIB = r(0.1f, 4.0f);
    c.normal = normalize(Vec2{r(-1.0f, 1.0f), r(0.2f, 1.0f)});
    c.friction = r(0.0f, 1.0f);
    c.rollingResistance = rolling ? r(0.01f, 0.2f) : 0.0f;
    c.rollingMass = rolling ? 1.0f / (c.invIA + c.invIB) : 0.0f;
    c.rollingImpulse = rolling ? r(-0.1f, 0.1f) : 0.0f;
    c.tangentSpeed = kinds.conveyor ? r(-0.5f, 0.5f) : 0.0f;
    c.restitution = !kinds.elastic || r(0.0f, 1.0f) < 0.3f ? 0.0f : r(0.1f, 1.0f);
    c.turnsA = kinds.flat || r(0.0f, 1.0f) < 0.5f ? 1.0f : 0.0f;
    c.turnsB = kinds.flat || r(0.0f, 1.0f) < 0.5f ? 1.0f : 0.0f;
    for (int i = 0; i < pointCount; ++i) {
        ContactPointRows<float>& p = c.points[i];
        p.anchorA = {r(-0.5f, 0.5f), r(-0.5f, 0.5f)};
        p.anchorB = {r(-0.5f, 0.5f), r(-0.5f, 0.5f)};
        p.baseSeparation = r(-0.05f, 0.02f);
        p.normalImpulse = r(0.0f, 1.0f);
        p.tangentImpulse = r(-0.2f, 0.2f);
        p.normalMass = r(0.2f, 2.0f);
        p.tangentMass = r(0.2f, 2.0f);
        c.relativeVelocity[i] = r(-4.0f, 0.5f);  // a threshold of 1 m/s: some approaches bounce
    }
    return c;
}

TEST(ContactSolverWide, FourLanesEqualFourScalarSolves) {
    StepContext ctx;
    ctx.invHs = 240.0f;
    ctx.restitutionThreshold = 1.0f;
    ctx.substeps = 4;
    ctx.h = 1.0f / 60.0f;
    ctx.invH = 60.0f;
    Random r{987654321u};
    int recordedPushes = 0;
    for (int round = 0; round < 50; ++round) {
        // The rows' softness, against the static body (lane 2) or not, comes from the step.
        ctx.contactSoftness = {r(10.0f, 60.0f), r(0.5f, 1.0f), r(0.0f, 0.5f)};
        ctx.staticSoftness = {r(10.0f, 60.0f), r(0.5f, 1.0f), r(0.0f, 0.5f)};
        ctx.hitEvents = round % 5 == 4;
        // Lanes: a two-point manifold, a one-point one with rolling resistance (unless round % 3 is
        // 2), one against the static slot 0, and an empty lane (round % 2) or another two-point
        // manifold. Every third round is flat, plain contacts: no round surface, tangent speed or
        // restitution; the next rolls where the others do, the one after has none of these.
        const bool emptyLast = round % 2 == 0;
        const Kinds kinds = round % 3 == 0 ? Kinds{true, false, false} : Kinds{};
        const bool rolls = round % 3 != 2;
        std::vector<BodyState> states(9);
        for (int i = 1; i < 9; ++i) states[i] = randomBody(r);
        std::array<ContactRows<float>, 4> rows = {randomRows(r, 2, false, kinds), randomRows(r, 1, rolls, kinds),
                                                  randomRows(r, 2, false, kinds),
                                                  emptyLast ? ContactRows<float>{} : randomRows(r, 2, rolls, kinds)};
        rows[2].invIA = 0.0f;  // body A of lane 2 is the static slot 0 (its state's 1/m is 0)
        const int bodyA[4] = {1, 3, 0, emptyLast ? 0 : 7};
        const int bodyB[4] = {2, 4, 5, emptyLast ? 0 : 8};

        std::vector<BodyState> scalar = states;
        std::array<ContactRows<float>, 4> scalarRows = rows;
        for (const bool useBias : {true, false}) {
            for (int lane = 0; lane < (emptyLast ? 3 : 4); ++lane) {
                warmStartContact(scalarRows[lane], scalar[bodyA[lane]], scalar[bodyB[lane]]);
                if (useBias) solveContact<true>(scalarRows[lane], scalar[bodyA[lane]], scalar[bodyB[lane]], ctx);
                else solveContact<false>(scalarRows[lane], scalar[bodyA[lane]], scalar[bodyB[lane]], ctx);
            }
        }
        // Each body's velocity change per substep from gravity-like forces: the rebound's deceleration.
        std::vector<SubstepForces> forces(9);
        for (int i = 1; i < 9; ++i) forces[i].dv = {r(-0.02f, 0.02f), r(-0.06f, 0.0f)};
        for (int lane = 0; lane < (emptyLast ? 3 : 4); ++lane)
            restituteContact(scalarRows[lane], scalar[bodyA[lane]], scalar[bodyB[lane]], LaneBodies<float>::velocityChange(forces.data(), bodyA[lane]),
                             LaneBodies<float>::velocityChange(forces.data(), bodyB[lane]), ctx);

        ContactRows<simd::Float4> wide = lanes_test::lanesOf<ContactRows>(rows);
        const RowUses uses = rowUses(floatsOf(wide), 4, emptyLast ? 3 : 4);
        EXPECT_EQ(uses.roundSurface, kinds.flat ? false : uses.roundSurface) << round;
        EXPECT_EQ(uses.conveyor || uses.elastic, !kinds.flat) << round;
        EXPECT_EQ(uses.rolling, rolls) << round;
        for (const bool useBias : {true, false}) {
            BodyLanes<simd::Float4> a = LaneBodies<simd::Float4>::gather(states.data(), bodyA), b = LaneBodies<simd::Float4>::gather(states.data(), bodyB);
            warmStartContact(wide, a, b, uses);
            if (useBias) solveContact<true>(wide, a, b, ctx, uses);
            else solveContact<false>(wide, a, b, ctx, uses);
            LaneBodies<simd::Float4>::scatter(states.data(), bodyA, a);
            LaneBodies<simd::Float4>::scatter(states.data(), bodyB, b);
        }
        if (uses.elastic) {  // as the solver: blocks without restitution skip its pass
            BodyLanes<simd::Float4> a = LaneBodies<simd::Float4>::gather(states.data(), bodyA), b = LaneBodies<simd::Float4>::gather(states.data(), bodyB);
            restituteContact(wide, a, b, LaneBodies<simd::Float4>::velocityChange(forces.data(), bodyA), LaneBodies<simd::Float4>::velocityChange(forces.data(), bodyB), ctx);
            LaneBodies<simd::Float4>::scatter(states.data(), bodyA, a);
            LaneBodies<simd::Float4>::scatter(states.data(), bodyB, b);
        }

        for (int i = 0; i < 9; ++i) {
            EXPECT_TRUE(sameBits(states[i].v.x, scalar[i].v.x)) << "round " << round << " body " << i;
            EXPECT_TRUE(sameBits(states[i].v.y, scalar[i].v.y)) << "round " << round << " body " << i;
            EXPECT_TRUE(sameBits(states[i].w, scalar[i].w)) << "round " << round << " body " << i;
        }
        float normal[4], tangent[4], rolling[4], maxNormal[4];
        wide.rollingImpulse.store(rolling);
        for (int lane = 0; lane < 4; ++lane) EXPECT_TRUE(sameBits(rolling[lane], scalarRows[lane].rollingImpulse)) << lane;
        for (int i = 0; i < 2; ++i) {
            wide.points[i].normalImpulse.store(normal);
            wide.points[i].tangentImpulse.store(tangent);
            wide.maxNormalImpulse[i].store(maxNormal);
            for (int lane = 0; lane < 4; ++lane) {
                // Recorded where restitution or hit events read it, else 0.
                if (ctx.hitEvents || scalarRows[lane].restitution != 0.0f) {
                    recordedPushes += scalarRows[lane].maxNormalImpulse[i] > 0.0f ? 1 : 0;
                } else {
                    EXPECT_EQ(scalarRows[lane].maxNormalImpulse[i], 0.0f);
                }
                EXPECT_TRUE(sameBits(maxNormal[lane], scalarRows[lane].maxNormalImpulse[i])) << lane;
                EXPECT_TRUE(sameBits(normal[lane], scalarRows[lane].points[i].normalImpulse)) << lane;
                EXPECT_TRUE(sameBits(tangent[lane], scalarRows[lane].points[i].tangentImpulse)) << lane;
            }
        }
    }
    EXPECT_GT(recordedPushes, 20);
}

// deriveContactRows (the prepared fields computed from a contact's gathered values) on four lanes
// gives every field the bits of four derivations at F = float: one-point manifolds, a static body,
// rolling resistance or none, with and without warm starting.
TEST(ContactSolverWide, DerivedRowsInFourLanesEqualFourScalarDerivations) {
    StepContext ctx;
    ctx.contactSoftness = {30.0f, 0.8f, 0.2f};
    ctx.staticSoftness = {60.0f, 0.9f, 0.1f};
    Random r{123456789u};
    for (int round = 0; round < 40; ++round) {
        ctx.enableWarmStarting = round % 4 != 3;
        std::vector<BodyState> free(9);
        for (int i = 1; i < 9; ++i) free[i] = randomBody(r);
        const int pointCounts[4] = {2, 1, 2, round % 2 == 0 ? 1 : 2};
        std::array<ContactRows<float>, 4> rows;
        for (int lane = 0; lane < 4; ++lane) {
            rows[lane] = randomRows(r, pointCounts[lane], lane % 2 == 1);
            for (int i = 0; i < pointCounts[lane]; ++i) rows[lane].points[i].baseSeparation = r(-0.05f, 0.05f);  // the separation
        }
        rows[2].invIA = 0.0f;  // body A of lane 2 is the static slot 0 (its state's 1/m is 0)
        const int bodyA[4] = {1, 3, 0, 7};
        const int bodyB[4] = {2, 4, 5, 8};

        ContactRows<simd::Float4> wide = lanes_test::lanesOf<ContactRows>(rows);
        float present[2][4];
        for (int lane = 0; lane < 4; ++lane)
            for (int i = 0; i < 2; ++i) present[i][lane] = i < pointCounts[lane] ? 1.0f : 0.0f;
        const simd::Float4 points[2] = {simd::Float4::load(present[0]), simd::Float4::load(present[1])};
        deriveContactRows(wide, LaneBodies<simd::Float4>::gather(free.data(), bodyA), LaneBodies<simd::Float4>::gather(free.data(), bodyB), points, ctx);

        for (int lane = 0; lane < 4; ++lane) {
            const float lanePresent[2] = {present[0][lane], present[1][lane]};
            deriveContactRows(rows[lane], free[bodyA[lane]], free[bodyB[lane]], lanePresent, ctx);
            const auto* scalar = reinterpret_cast<const float*>(&rows[lane]);
            const auto* lanes = reinterpret_cast<const float*>(&wide);
            for (std::size_t field = 0; field < rowFloats; ++field)
                EXPECT_TRUE(sameBits(lanes[field * 4 + static_cast<std::size_t>(lane)], scalar[field]))
                    << "round " << round << " lane " << lane << " field " << field;
        }
        EXPECT_GT(rows[0].points[0].normalMass, 0.0f);
        EXPECT_EQ(rows[1].points[1].normalMass, 0.0f);  // no second point: no mass
    }
}

}  // namespace
}  // namespace perpdot
