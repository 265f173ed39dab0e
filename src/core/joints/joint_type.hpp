// How a joint type's file hands its type to the store. joint_<type>.cpp holds the type's data
// struct, the struct's field list (field_list.hpp), `Joint& makeJoint(World::Impl&, const
// RopeJointDef&)` and its stages, and ends with
//
//     template JointId World::createJoint(const RopeJointDef&);
//     extern const JointKind ropeKind = jointKind<RopeJoint>({prepareRope, warmStartRope, solveRope, reactionRope});
//
// the public createJoint for its definition and its kind, which joint_registry.cpp lists. jointKind instantiates here, beside the list, what the store and
// the snapshot do with the type's data: JointData's checks that the struct fits and is trivially
// copyable, writing and reading it through its field list, and format 1's raw layout.
#pragma once

#include "core/joints/joint_store.hpp"
#include "core/snapshot/math_fields.hpp"

namespace perpdot {

// Defined here for the explicit instantiation in each type's file: makeJoint checks the
// definition, adds the joint (addJoint) and emplaces its data.
template <JointDef Def>
JointId World::createJoint(const Def& def) {
    return jointId(*impl_, makeJoint(*impl_, def));
}

// T's kind; `motorSpeed` names T's motor speed for World::setMotorSpeed (none: no motor).
template <class T, float T::*motorSpeed = nullptr>
constexpr JointKind jointKind(const JointStages& stages) {
    JointKind kind{stages, [](ByteWriter& out, const JointData& data) { writeFields(out, data.as<T>()); },
                   [](ByteReader& in, JointData& data) {
                       T& value = data.emplace<T>();  // value-initialised, as createJoint starts it
                       if (in.version == 1) {
                           size_t offset = 0;
                           readLayoutV1(in, value, offset);
                       } else {
                           readFields(in, value);
                       }
                   },
                   nullptr};
    if constexpr (motorSpeed != nullptr) kind.motorSpeed = [](JointData& data) { return &(data.as<T>().*motorSpeed); };
    return kind;
}

}  // namespace perpdot
