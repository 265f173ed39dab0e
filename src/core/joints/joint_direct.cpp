// The rows of revolute, weld and prismatic joints as a direct solve takes them (joint_direct.hpp):
// the same rows the joints' own passes solve, at step start for a contact group (joint.hpp,
// contact_groups.hpp) or now for a joint tree, and their position errors now.
#include "core/joints/joint_direct.hpp"

#include <type_traits>

#include "core/joints/joint_prismatic.hpp"
#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_rows.hpp"
#include "core/joints/joint_weld.hpp"
#include "core/world/step_scratch.hpp"

namespace perpdot {

namespace {

DirectJointRow equalityRow(const Row& r) { return {r.n, r.sA, r.sB, false}; }
DirectJointRow limitRow(const Row& r) { return {r.n, r.sA, r.sB, true}; }

// The rows at frame f (the arms rA, rB and d = pB − pA), a prismatic joint's along `axis`, its axis
// in the world; the axis rows take A's arm to B's anchor, rA + d.
int rowsAt(const PreparedJoint& j, const JointFrame& f, Vec2 axis, DirectJointRow* rows) {
    const Row pointX = linearRow(f.rA, f.rB, Vec2{1.0f, 0.0f}), pointY = linearRow(f.rA, f.rB, Vec2{0.0f, 1.0f});
    switch (j.type) {
        case JointType::Revolute:
            rows[0] = equalityRow(pointX), rows[1] = equalityRow(pointY);
            if (!j.data.as<RevoluteJoint>().enableLimit) return 2;
            rows[2] = limitRow(angularRow), rows[3] = limitRow(negated(angularRow));
            return 4;
        case JointType::Weld:
            rows[0] = equalityRow(pointX), rows[1] = equalityRow(pointY), rows[2] = equalityRow(angularRow);
            return 3;
        case JointType::Prismatic: {
            const Row axial = linearRow(f.rA + f.d, f.rB, axis);
            rows[0] = equalityRow(linearRow(f.rA + f.d, f.rB, perp(axis))), rows[1] = equalityRow(angularRow);
            if (!j.data.as<PrismaticJoint>().enableLimit) return 2;
            rows[2] = limitRow(axial), rows[3] = limitRow(negated(axial));
            return 4;
        }
        default: return 0;
    }
}

}  // namespace

int equalityRowCount(JointType type) { return type == JointType::Weld ? 3 : 2; }

int jointRowsNow(const PreparedJoint& j, const JointPair& p, DirectJointRow* rows) {
    const Vec2 axis = j.type == JointType::Prismatic ? rotate(p.a.dq, j.data.as<PrismaticJoint>().axisA) : Vec2{};
    return rowsAt(j, currentFrame(j, p), axis, rows);
}

int awakeJointCount(const JointScratch& d) { return static_cast<int>(d.prepared.size()); }

std::pair<int, int> jointSlots(const JointScratch& d, int k) { return {d.prepared[k].indexA, d.prepared[k].indexB}; }

int directJointRows(const JointScratch& d, int k, DirectJointRow* rows) {
    const PreparedJoint& j = d.prepared[k];
    if (j.breakable) return 0;  // its substeps' impulses are summed one joint at a time (breakJoints)
    switch (j.type) {
        case JointType::Revolute:
            if (j.data.as<RevoluteJoint>().enableMotor) return 0;
            break;
        case JointType::Weld:
            if (j.data.as<WeldJoint>().hertz > 0.0f) return 0;
            break;
        case JointType::Prismatic:
            if (j.data.as<PrismaticJoint>().enableMotor) return 0;
            break;
        default: return 0;
    }
    // At step start: the arms as prepared, d = (cB − cA)₀ + rB − rA, the axis as prepared.
    const Vec2 axis = j.type == JointType::Prismatic ? j.data.as<PrismaticJoint>().axisA : Vec2{};
    return rowsAt(j, JointFrame{j.anchorA, j.anchorB, j.deltaCenter + j.anchorB - j.anchorA}, axis, rows);
}

void jointRowErrors(const PreparedJoint& j, const JointPair& p, float* C) {
    const float angle = currentAngle(j, p);
    switch (j.type) {
        case JointType::Revolute: {
            const RevoluteJoint& r = j.data.as<RevoluteJoint>();
            const Vec2 gap = currentFrame(j, p).d;
            C[0] = gap.x, C[1] = gap.y, C[2] = angle - r.lowerAngle, C[3] = r.upperAngle - angle;
            return;
        }
        case JointType::Weld: {
            const Vec2 gap = currentFrame(j, p).d;
            C[0] = gap.x, C[1] = gap.y, C[2] = angle;
            return;
        }
        case JointType::Prismatic: {
            const PrismaticJoint& s = j.data.as<PrismaticJoint>();
            const AxisRowsT<float> axis = axisRows(p, j.anchorA, j.anchorB, j.deltaCenter, s.axisA);
            C[0] = axis.offset, C[1] = angle, C[2] = axis.translation - s.lower, C[3] = s.upper - axis.translation;
            return;
        }
        default: return;
    }
}

void directJointErrors(const JointScratch& d, SolverBodies& bodies, int k, float* C) {
    const PreparedJoint& j = d.prepared[k];
    jointRowErrors(j, pairOf(bodies.states, bodies.stepRotation, j), C);
}

namespace {

// Where row `row` of a joint keeps its accumulated λ; J is PreparedJoint, const or not.
template <class J>
auto& impulseOf(J& j, int row) {
    using Impulse = std::conditional_t<std::is_const_v<J>, const float, float>;
    switch (j.type) {
        case JointType::Revolute: {
            auto& r = j.data.template as<RevoluteJoint>();
            Impulse* rows[] = {&r.linearImpulse.x, &r.linearImpulse.y, &r.lowerImpulse, &r.upperImpulse};
            return *rows[row];
        }
        case JointType::Weld: {
            auto& s = j.data.template as<WeldJoint>();
            Impulse* rows[] = {&s.linearImpulse.x, &s.linearImpulse.y, &s.angularImpulse};
            return *rows[row];
        }
        default: {
            auto& s = j.data.template as<PrismaticJoint>();
            Impulse* rows[] = {&s.impulse.x, &s.impulse.y, &s.lowerImpulse, &s.upperImpulse};
            return *rows[row];
        }
    }
}

}  // namespace

float& jointRowImpulse(PreparedJoint& j, int row) { return impulseOf(j, row); }

void solveJointDirectly(JointScratch& d, int k) {
    d.direct[k] = 1;
    d.keys[k].treeJoint = false;  // no joint tree takes it
}

float directJointImpulse(const JointScratch& d, int k, int row) { return impulseOf(d.prepared[k], row); }

void setDirectJointImpulse(JointScratch& d, int k, int row, float impulse) { impulseOf(d.prepared[k], row) = impulse; }

}  // namespace perpdot
