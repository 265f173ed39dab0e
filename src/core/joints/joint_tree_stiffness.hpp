// Geometric stiffness of joint trees (Andrews, Teichmann, Kry, "Geometric Stiffness for
// Real-time Constrained Multibody Dynamics", 2017). A chain pulled taut by a heavy end has
// transverse modes as fast as ω ≈ √(T / (m·l)): the tension T of a 1000:1 end turns a 50 g link
// at hundreds of rad/s, beyond what a substep's velocity solve (the Jacobian held at the
// substep's start) follows, and the anchors drift apart by metres. The torque a joint force f
// exerts at arm r, τ = r × f, varies with the body's angle as ∂τ/∂θ = −r·f; its diagonal, taken
// implicitly over the substep, adds to the body's inertia as the joints of the tree see it:
//   Ĩ = I + hs²·Σ|r·f| = I + hs·Σ|r·λ|,   f = λ/hs,
// λ each joint's accumulated impulse at the step's start (the warm start). It slows the fast
// turning under tension only; forces, momentum and the slack motion stay as they were.
#pragma once

#include <vector>

#include "core/joints/joint_tree.hpp"

namespace perpdot {

// Each tree joint's inverse inertias become 1/Ĩ of its bodies; `slots` is the solver's body count.
void stiffenJointTrees(JointTrees& trees, std::vector<PreparedJoint>& prepared, float hs, int slots);

}  // namespace perpdot
