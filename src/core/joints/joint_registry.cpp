// The joint types by JointType: adding a type is its joint_<type>.cpp, which ends with its
// JointKind, and its line here (docs/joints.md, "Adding a joint type").
#include <array>

#include "core/joints/joint_store.hpp"

namespace perpdot {

extern const JointKind revoluteKind, prismaticKind, distanceKind, weldKind, wheelKind, motorKind, mouseKind, gearKind,
    pulleyKind, filterKind, frictionKind;

namespace {

// In JointType's order; jointTypeCount (joint_store.hpp) names the last enumerator.
constexpr std::array registry{&revoluteKind, &prismaticKind, &distanceKind, &weldKind, &wheelKind,
                              &motorKind,    &mouseKind,     &gearKind,     &pulleyKind, &filterKind, &frictionKind};
static_assert(registry.size() == jointTypeCount, "a JointType without a kind");

}  // namespace

const JointKind* kindOf(JointType type) {
    const auto index = static_cast<size_t>(type);
    return index < registry.size() ? registry[index] : nullptr;
}

const JointStages& stagesOf(JointType type) { return registry[static_cast<size_t>(type)]->stages; }

}  // namespace perpdot
