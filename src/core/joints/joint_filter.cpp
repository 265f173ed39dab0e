// Filter joint: no rows; its bodies do not collide (collideConnected false, which addJoint acts
// on). Box2D v3's filter joint.
#include <tuple>

#include "core/bodies/body_store.hpp"
#include "core/joints/joint_type.hpp"

namespace perpdot {

namespace {

struct FilterJoint {};

constexpr auto fields(const FilterJoint*) { return std::tuple{}; }

void prepareFilter(PreparedJoint&, const StepContext&, const Body&, const Body&) {}
void warmStartFilter(PreparedJoint&, JointPair&) {}
void solveFilter(PreparedJoint&, JointPair&, const StepContext&, bool) {}
JointReaction reactionFilter(const JointData&) { return {}; }

}  // namespace

Joint& makeJoint(World::Impl& w, const FilterJointDef& def) {
    Joint& j = addJoint(w, JointType::Filter, def.bodyA, def.bodyB, {}, {}, 0.0f, false, def.userData);
    j.data.emplace<FilterJoint>();
    return j;
}

template JointId World::createJoint(const FilterJointDef&);
extern const JointKind filterKind = jointKind<FilterJoint>({prepareFilter, warmStartFilter, solveFilter, reactionFilter});

}  // namespace perpdot
