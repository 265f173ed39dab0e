// The events of the last step, owned by the world and read after step() through spans (Box2D v3's
// model): raised while the step runs, buffered without allocating once the buffers have grown.
// End events raised between steps (a shape or body destroyed) are kept for the next step.
#pragma once

#include <cstddef>
#include <vector>

#include "perpdot/world.hpp"

namespace perpdot {

struct EventBuffers {
    std::vector<ContactBeginTouchEvent> contactBegin;
    std::vector<ContactEndTouchEvent> contactEnd;
    std::vector<ContactHitEvent> contactHit;
    std::vector<JointBreakEvent> jointBreak;
    std::vector<SensorBeginTouchEvent> sensorBegin;
    std::vector<SensorEndTouchEvent> sensorEnd;
    // The end events the last step reported: the first entries of contactEnd and sensorEnd. Those
    // after them were raised between steps and belong to the next one.
    size_t contactEndReported = 0, sensorEndReported = 0;

    // At the start of step(): the last step's events go, end events raised since stay.
    void beginStep() {
        contactBegin.clear();
        contactHit.clear();
        jointBreak.clear();
        sensorBegin.clear();
        contactEnd.erase(contactEnd.begin(), contactEnd.begin() + static_cast<std::ptrdiff_t>(contactEndReported));
        sensorEnd.erase(sensorEnd.begin(), sensorEnd.begin() + static_cast<std::ptrdiff_t>(sensorEndReported));
    }
    // The events of `other` in this world's buffers, whose capacity stays (a restore keeps the
    // restoring world's buffers: its next step allocates nothing).
    void assignKeepingCapacity(const EventBuffers& other) {
        auto copy = [](auto& to, const auto& from) { to.assign(from.begin(), from.end()); };
        copy(contactBegin, other.contactBegin);
        copy(contactEnd, other.contactEnd);
        copy(contactHit, other.contactHit);
        copy(jointBreak, other.jointBreak);
        copy(sensorBegin, other.sensorBegin);
        copy(sensorEnd, other.sensorEnd);
        contactEndReported = other.contactEndReported;
        sensorEndReported = other.sensorEndReported;
    }
    // At the end of step(): every end event so far is this step's.
    void endStep() {
        contactEndReported = contactEnd.size();
        sensorEndReported = sensorEnd.size();
    }
};

}  // namespace perpdot
