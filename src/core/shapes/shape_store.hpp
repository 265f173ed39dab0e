// Shapes as the world stores them, and the shape store: a Pool<ShapeData> (pool.hpp) that also
// remembers what every shape ever created had in it (filter bits, hit events), so that the
// broadphase can skip proxies whose filter rejects every shape. A ShapeId is (index, generation).
#pragma once

#include <cstdint>
#include <variant>
#include <vector>

#include "core/base/pool.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct ShapeData {
    uint32_t generation = 0;
    bool alive = false;
    int body = -1;
    ShapeType type = ShapeType::Circle;
    bool enabled = true;  // World::setEnabled(ShapeId): false keeps it out of the broadphase
    using Geometry = std::variant<Circle, Polygon, Segment, Chain, Capsule>;  // index = ShapeType
    Geometry geometry;
    float density = 1, friction = 0.6f, restitution = 0;
    float rollingResistance = 0, tangentSpeed = 0;
    bool sensor = false;
    bool enableContactEvents = true, enableHitEvents = false, enableSensorEvents = true, enablePreSolveEvents = false;
    float minExtent = 0, maxExtent = 0;  // about the body origin, for continuous collision
    Filter filter;
    void* userData = nullptr;
    std::vector<int> proxies;  // broadphase proxy of each child

    // ShapeData{}, keeping the proxy list's memory (Pool::restoreSlots).
    void resetKeepingMemory() {
        std::vector<int> keep = std::move(proxies);
        keep.clear();
        *this = ShapeData{};
        proxies = std::move(keep);
    }
};

struct ShapeStore : Pool<ShapeData> {
    bool anyHitEvents = false;  // a shape with enableHitEvents was ever created: look for hits
    // A shape was ever elastic (created, set or restored with restitution > 0): look for impacts
    // (impact_propagation.cpp). Without one no contact is elastic, so skipping the search changes nothing.
    bool anyRestitution = false;
    void noteRestitution(float restitution) { anyRestitution = anyRestitution || restitution > 0.0f; }
    // Every category and every mask bit of the shapes ever created (never cleared).
    uint16_t categories = 0, masks = 0;

    void noteFilter(const Filter& f) {
        categories |= f.category;
        masks |= f.mask;
    }
    // shouldCollide(f, g) is false for every shape's g: outside a positive group (which collides
    // whatever the masks), f's mask meets no category or f's category no mask.
    bool pairsWithNothing(const Filter& f) const {
        return f.group <= 0 && ((f.mask & categories) == 0 || (f.category & masks) == 0);
    }
};

// The radius a shape's surface is rounded by (a circle's, a capsule's, a rounded polygon's), 0 for
// flat surfaces: these meet other shapes at their vertices, which are points of the body.
inline float roundingRadius(const ShapeData& s) {
    if (auto* c = std::get_if<Circle>(&s.geometry)) return c->radius;
    if (auto* p = std::get_if<Polygon>(&s.geometry)) return p->radius;
    if (auto* c = std::get_if<Capsule>(&s.geometry)) return c->radius;
    return 0.0f;
}

// The geometry checks of createShape (shape.cpp), also run on restored snapshots: Error if invalid.
void validateGeometry(const Circle& circle);
void validateGeometry(const Polygon& polygon);
void validateGeometry(const Segment& segment);
void validateGeometry(const Chain& chain);
void validateGeometry(const Capsule& capsule);

}  // namespace perpdot
