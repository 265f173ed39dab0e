// Placeholder joint store until the joint rows land: no joints can be created yet.
#include "core/world_impl.hpp"

namespace perpdot {

struct JointStore {};
void JointStoreDeleter::operator()(JointStore* store) const { delete store; }
JointStorePtr makeJointStore() { return JointStorePtr(new JointStore); }

void prepareJoints(World::Impl&, const StepContext&) {}
void warmStartJoints(World::Impl&, const StepContext&) {}
void solveJoints(World::Impl&, const StepContext&, bool) {}
void storeJointImpulses(World::Impl&, const StepContext&) {}
bool jointAllowsCollision(const World::Impl&, int, int) { return true; }
void destroyJointsOf(World::Impl&, int) {}
void forEachJointPair(const World::Impl&, void (*)(void*, int, int), void*) {}

namespace {
[[noreturn]] void notYet() { throw Error("joints are not implemented yet"); }
}  // namespace

JointId World::createJoint(const RevoluteJointDef&) { notYet(); }
JointId World::createJoint(const PrismaticJointDef&) { notYet(); }
JointId World::createJoint(const DistanceJointDef&) { notYet(); }
JointId World::createJoint(const WeldJointDef&) { notYet(); }
JointId World::createJoint(const WheelJointDef&) { notYet(); }
JointId World::createJoint(const MotorJointDef&) { notYet(); }
JointId World::createJoint(const MouseJointDef&) { notYet(); }
void World::destroyJoint(JointId) { notYet(); }
bool World::isValid(JointId) const { return false; }
std::vector<JointId> World::joints() const { return {}; }
JointType World::jointType(JointId) const { notYet(); }
BodyId World::jointBodyA(JointId) const { notYet(); }
BodyId World::jointBodyB(JointId) const { notYet(); }
Vec2 World::jointAnchorA(JointId) const { notYet(); }
Vec2 World::jointAnchorB(JointId) const { notYet(); }
Vec2 World::jointReactionForce(JointId) const { notYet(); }
float World::jointReactionTorque(JointId) const { notYet(); }
void World::setMouseTarget(JointId, Vec2) { notYet(); }
void World::setMotorSpeed(JointId, float) { notYet(); }

}  // namespace perpdot
