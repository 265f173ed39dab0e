// Weld joint: the point rows of the revolute joint plus one angular row (effective mass
// 1/(1/IA + 1/IB)) holding θB − θA at the reference angle. With hertz > 0 the angular row is a
// spring (Box2D 2.4's soft weld bends; it does not stretch). The rows are written once over a lane
// type F, for one joint and for blocks of four (joint_solver_wide.hpp).
#include <cmath>
#include <cstddef>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_solver_wide.hpp"
#include "core/joints/joint_type.hpp"
#include "core/joints/joint_weld.hpp"

namespace perpdot {

namespace {

// The weld joint's rows: the point rows, then the angle row, rigid or a spring by lane.
struct WeldRowSet {
    template <class F>
    struct Rows {
        Vec2T<F> anchorA, anchorB;  // rA, rB at step start
        Vec2T<F> deltaCenter;       // cB − cA at step start
        Vec2T<F> linearImpulse;     // λ of the point rows
        F angularImpulse{};         // λ of the angle row
        F deltaAngle{};             // θB − θA − θref at step start
        F axialMass{};              // 1 / (1/IA + 1/IB)
        F spring{};                 // 1 where hertz > 0, else 0
        SoftnessT<F> angularSoftness;  // the spring's
    };

    static bool optionalRows(const PreparedJoint&) { return false; }
    static bool usesRotation(bool) { return true; }

    template <std::size_t lanes>
    static void gather(const PreparedJoint& j, RowLane<lanes> out, bool) {
        using R = Rows<float>;
        const WeldJoint& s = j.data.as<WeldJoint>();
        gatherPointAndAngle<R>(j, s, out);
        out.set(offsetof(R, spring), s.hertz > 0.0f ? 1.0f : 0.0f);
        out.set(offsetof(R, angularSoftness), s.angularSoftness);
    }

    // Re-apply last step's impulses: λ at the anchors, then the angle's on ωB − ωA.
    template <class F>
    static void warmStart(const Rows<F>& r, JointPairT<F>& p) {
        warmStartPointAndAngle(r, p);
    }

    // One pass: the angle row on θ = (θB − θA − θref)₀ + p.rotation, then the point rows on
    // C = pB − pA.
    template <class F>
    static void solve(Rows<F>& r, JointPairT<F>& p, const StepContext& ctx, bool useBias, bool) {
        const Softness rigid = rigidSoftness(ctx, useBias);
        const SoftnessT<F> angular = selectSoftness<F>(r.spring != F(0.0f), r.angularSoftness, rigid);
        solveRow(p, angularRowOf<F>(), r.axialMass, r.deltaAngle + p.rotation, angular, r.angularImpulse);
        const JointFrameT<F> f = currentFrame(p, r.anchorA, r.anchorB, r.deltaCenter);
        solvePointRows(p, f.rA, f.rB, f.d, rigid, r.linearImpulse);
    }

    // The impulses, and what prepareWeld wrote (snapshots carry it).
    template <std::size_t lanes>
    static void store(RowLane<lanes, const float> rows, JointData& data, bool) {
        using R = Rows<float>;
        WeldJoint& s = data.as<WeldJoint>();
        storePointAndAngle<R>(rows, s);
        s.angularSoftness = rows.softness(offsetof(R, angularSoftness));
    }
};

constexpr JointLaneStages weldLanes = jointLaneStages<WeldRowSet>();

}  // namespace

Joint& makeJoint(World::Impl& w, const WeldJointDef& def) {
    requireFinite(std::isfinite(def.hertz) && std::isfinite(def.dampingRatio), "WeldJointDef spring");
    if (def.hertz < 0.0f || def.dampingRatio < 0.0f) throw Error("WeldJointDef: hertz and dampingRatio must be >= 0");
    Joint& j = addJoint(w, JointType::Weld, def.bodyA, def.bodyB, def.localAnchorA, def.localAnchorB,
                        def.referenceAngle, def.collideConnected, def.userData);
    WeldJoint& s = j.data.emplace<WeldJoint>();
    s.hertz = def.hertz;
    s.dampingRatio = def.dampingRatio;
    return j;
}

void prepareWeld(PreparedJoint& j, const StepContext& ctx, const Body&, const Body&) {
    WeldJoint& s = j.data.as<WeldJoint>();
    s.axialMass = effectiveMass(j.mass, angularRow);
    s.angularSoftness = makeSoftness(s.hertz, s.dampingRatio, ctx.hs);
    if (!ctx.enableWarmStarting) {
        s.linearImpulse = {};
        s.angularImpulse = 0.0f;
    }
}

JointReaction reactionWeld(const JointData& data) { return {data.as<WeldJoint>().linearImpulse, data.as<WeldJoint>().angularImpulse}; }

template JointId World::createJoint(const WeldJointDef&);
extern const JointKind weldKind = jointKind<WeldJoint>(
    {prepareWeld, warmStartJoint<WeldRowSet>, solveJoint<WeldRowSet>, reactionWeld, &weldLanes});

}  // namespace perpdot
