#include "core/joints/joint_tree_stiffness.hpp"

#include <cmath>

#include "core/joints/joint_revolute.hpp"
#include "core/joints/joint_rows.hpp"
#include "core/joints/joint_store.hpp"

namespace perpdot {

void stiffenRevoluteTrees(RevoluteTrees& t, std::vector<PreparedJoint>& prepared, float hs, int slots) {
    if (t.joints.empty()) return;
    // Σ|r·λ| by solver slot, over the tree joints at the body (slot 0, static, gathers and is unused).
    t.stiffness.assign(slots, 0.0f);
    for (int k : t.joints) {
        const PreparedJoint& j = prepared[k];
        const Vec2 lambda = j.data.as<RevoluteJoint>().linearImpulse;
        t.stiffness[j.indexA] += std::fabs(dot(j.anchorA, lambda));
        t.stiffness[j.indexB] += std::fabs(dot(j.anchorB, lambda));
    }
    // 1/Ĩ = 1/(I + hs·Σ|r·λ|) = invI / (1 + invI·hs·Σ|r·λ|); a body that cannot turn keeps 0.
    for (int k : t.joints) {
        PreparedJoint& j = prepared[k];
        j.mass.iA /= 1.0f + j.mass.iA * hs * t.stiffness[j.indexA];
        j.mass.iB /= 1.0f + j.mass.iB * hs * t.stiffness[j.indexB];
        // The angle rows' effective mass 1/(1/ĨA + 1/ĨB) (joint_revolute.cpp's prepare, on Ĩ).
        RevoluteJoint& r = j.data.as<RevoluteJoint>();
        r.axialMass = effectiveMass(j.mass, angularRow);
    }
}

}  // namespace perpdot
