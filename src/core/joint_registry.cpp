// The joint types' solver stages by JointType: adding a type is its joint_<type>.cpp, which ends
// with its JointStages, and one line here (docs/joints.md, "Adding a joint type").
#include <array>

#include "core/joint_store.hpp"

namespace perpdot {

extern const JointStages revoluteStages, prismaticStages, distanceStages, weldStages, wheelStages, motorStages,
    mouseStages, gearStages, pulleyStages;

namespace {

// In JointType's order. The assert names the last enumerator: a new type moves it there.
constexpr std::array registry{&revoluteStages, &prismaticStages, &distanceStages, &weldStages, &wheelStages,
                              &motorStages,    &mouseStages,     &gearStages,     &pulleyStages};
static_assert(registry.size() == static_cast<size_t>(JointType::Pulley) + 1, "a JointType without stages");

}  // namespace

const JointStages& stagesOf(JointType type) { return *registry[static_cast<size_t>(type)]; }

}  // namespace perpdot
