// The rows of revolute, weld and prismatic joints as a contact group's direct solve takes them
// (joint.hpp, contact_groups.hpp): the same rows the joints' own passes solve, with the arms at
// step start, and their position errors now.
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

// The axis rows at step start (axisRows at no motion): A's arm to B's anchor is rA + d.
AxisRowsT<float> startAxisRows(const PreparedJoint& j, Vec2 axis) {
    const Vec2 d = j.deltaCenter + j.anchorB - j.anchorA;
    return {linearRow(j.anchorA + d, j.anchorB, axis), linearRow(j.anchorA + d, j.anchorB, perp(axis)), dot(axis, d), dot(perp(axis), d)};
}

}  // namespace

int awakeJointCount(const JointScratch& d) { return static_cast<int>(d.prepared.size()); }

std::pair<int, int> jointSlots(const JointScratch& d, int k) { return {d.prepared[k].indexA, d.prepared[k].indexB}; }

int directJointRows(const JointScratch& d, int k, DirectJointRow* rows) {
    const PreparedJoint& j = d.prepared[k];
    if (j.breakable) return 0;  // its substeps' impulses are summed one joint at a time (breakJoints)
    const Row pointX = linearRow(j.anchorA, j.anchorB, Vec2{1.0f, 0.0f}), pointY = linearRow(j.anchorA, j.anchorB, Vec2{0.0f, 1.0f});
    switch (j.type) {
        case JointType::Revolute: {
            const RevoluteJoint& r = j.data.as<RevoluteJoint>();
            if (r.enableMotor) return 0;
            rows[0] = equalityRow(pointX), rows[1] = equalityRow(pointY);
            if (!r.enableLimit) return 2;
            rows[2] = limitRow(angularRow), rows[3] = limitRow(negated(angularRow));
            return 4;
        }
        case JointType::Weld:
            if (j.data.as<WeldJoint>().hertz > 0.0f) return 0;
            rows[0] = equalityRow(pointX), rows[1] = equalityRow(pointY), rows[2] = equalityRow(angularRow);
            return 3;
        case JointType::Prismatic: {
            const PrismaticJoint& s = j.data.as<PrismaticJoint>();
            if (s.enableMotor) return 0;
            const AxisRowsT<float> axis = startAxisRows(j, s.axisA);
            rows[0] = equalityRow(axis.perpendicular), rows[1] = equalityRow(angularRow);
            if (!s.enableLimit) return 2;
            rows[2] = limitRow(axis.axial), rows[3] = limitRow(negated(axis.axial));
            return 4;
        }
        default: return 0;
    }
}

void directJointErrors(const JointScratch& d, SolverBodies& bodies, int k, float* C) {
    const PreparedJoint& j = d.prepared[k];
    const JointPair p = pairOf(bodies.states, bodies.stepRotation, j);
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

namespace {

// Where row `row` of a joint keeps its accumulated λ (directJointRows' order); J is PreparedJoint,
// const or not.
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

void solveJointDirectly(JointScratch& d, int k) {
    d.direct[k] = 1;
    d.keys[k].hinge = false;  // no revolute tree takes it
}

float directJointImpulse(const JointScratch& d, int k, int row) { return impulseOf(d.prepared[k], row); }

void setDirectJointImpulse(JointScratch& d, int k, int row, float impulse) { impulseOf(d.prepared[k], row) = impulse; }

}  // namespace perpdot
