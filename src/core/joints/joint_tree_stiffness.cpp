#include "core/joints/joint_tree_stiffness.hpp"

#include <cmath>

#include "core/joints/joint_prismatic.hpp"
#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_rows.hpp"
#include "core/joints/joint_store.hpp"
#include "core/joints/joint_weld.hpp"

namespace perpdot {

void stiffenJointTrees(JointTrees& t, std::vector<PreparedJoint>& prepared, float hs, int slots) {
    if (t.joints.empty()) return;
    // Σ|r·λ| by solver slot, over the tree joints at the body (slot 0, static, gathers and is unused),
    // λ the joint's accumulated linear impulse on B (its reaction; a prismatic joint's along and
    // across its axis), at the anchors.
    t.stiffness.assign(slots, 0.0f);
    for (int k : t.joints) {
        const PreparedJoint& j = prepared[k];
        const Vec2 lambda = stagesOf(j.type).reaction(j.data).linear;
        t.stiffness[j.indexA] += std::fabs(dot(j.anchorA, lambda));
        t.stiffness[j.indexB] += std::fabs(dot(j.anchorB, lambda));
    }
    // 1/Ĩ = 1/(I + hs·Σ|r·λ|) = invI / (1 + invI·hs·Σ|r·λ|); a body that cannot turn keeps 0.
    for (int k : t.joints) {
        PreparedJoint& j = prepared[k];
        j.mass.iA /= 1.0f + j.mass.iA * hs * t.stiffness[j.indexA];
        j.mass.iB /= 1.0f + j.mass.iB * hs * t.stiffness[j.indexB];
        // The effective masses the joint's prepare wrote, on Ĩ: of the angle rows, or along the axis.
        switch (j.type) {
            case JointType::Revolute: j.data.as<RevoluteJoint>().axialMass = effectiveMass(j.mass, angularRow); break;
            case JointType::Weld: j.data.as<WeldJoint>().axialMass = effectiveMass(j.mass, angularRow); break;
            case JointType::Prismatic: {
                PrismaticJoint& s = j.data.as<PrismaticJoint>();
                s.axialMass = axialMass(j, s.axisA);
                break;
            }
            default: break;
        }
    }
}

}  // namespace perpdot
