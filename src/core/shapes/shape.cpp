// Shapes: validation, attachment to bodies (mass follows), and their broadphase proxies.
#include <algorithm>
#include <cmath>
#include <string>

#include "core/contacts/contact_world.hpp"
#include "core/world/world_impl.hpp"

namespace perpdot {

namespace {

void validate(const ShapeDef& def) {
    if (!(std::isfinite(def.density) && def.density >= 0.0f)) throw Error("ShapeDef.density must be finite and >= 0");
    if (!(std::isfinite(def.friction) && def.friction >= 0.0f)) throw Error("ShapeDef.friction must be finite and >= 0");
    if (!(std::isfinite(def.restitution) && def.restitution >= 0.0f)) throw Error("ShapeDef.restitution must be finite and >= 0");
    if (!(std::isfinite(def.rollingResistance) && def.rollingResistance >= 0.0f)) throw Error("ShapeDef.rollingResistance must be finite and >= 0");
    if (!std::isfinite(def.tangentSpeed)) throw Error("ShapeDef.tangentSpeed must be finite");
}

}  // namespace

void validateGeometry(const Circle& c) {
    if (!isFinite(c.center)) throw Error("circle center must be finite");
    if (!withinShapeRange(c.center)) throw Error("circle center is more than 100000 m from the body origin");
    if (!(std::isfinite(c.radius) && c.radius > 0.0f)) throw Error("circle radius must be finite and > 0");
    if (!withinShapeRange(c.radius)) throw Error("circle radius is more than 100000 m");
}

void validateGeometry(const Polygon& p) {
    // Re-run the construction checks: a hand-filled Polygon gets the same scrutiny as makePolygon's.
    makePolygon(std::span(p.vertices.data(), static_cast<size_t>(std::clamp(p.count, 0, maxPolygonVertices + 1))), p.radius);
}

void validateGeometry(const Segment& s) {
    if (!isFinite(s.v1) || !isFinite(s.v2)) throw Error("segment vertices must be finite");
    if (!withinShapeRange(s.v1) || !withinShapeRange(s.v2)) throw Error("segment vertex is more than 100000 m from the body origin");
    if (distance(s.v1, s.v2) < collide::linearSlop) throw Error("segment is shorter than the linear slop (0.005 m)");
}

void validateGeometry(const Chain& c) {
    const size_t minimum = c.loop ? 3 : 2;
    if (c.vertices.size() < minimum) throw Error("chain needs at least " + std::to_string(minimum) + " vertices");
    if (c.solid != ChainSide::Right && c.solid != ChainSide::Left) throw Error("chain solid side is neither Right nor Left");
    if (c.loop && (c.prevVertex || c.nextVertex)) throw Error("a chain loop takes no prevVertex or nextVertex (its neighbours are its own)");
    for (const std::optional<Vec2>& ghost : {c.prevVertex, c.nextVertex})
        if (ghost && (!isFinite(*ghost) || !withinShapeRange(*ghost)))
            throw Error("chain ghost vertex is not finite or more than 100000 m from the body origin");
    for (size_t i = 0; i < c.vertices.size(); ++i) {
        if (!isFinite(c.vertices[i])) throw Error("chain vertex " + std::to_string(i) + " is not finite");
        if (!withinShapeRange(c.vertices[i])) throw Error("chain vertex " + std::to_string(i) + " is more than 100000 m from the body origin");
        if (i > 0 && distance(c.vertices[i - 1], c.vertices[i]) < collide::linearSlop)
            throw Error("chain vertices " + std::to_string(i - 1) + " and " + std::to_string(i) + " are too close");
    }
}

void validateGeometry(const Capsule& c) {
    if (!isFinite(c.center1) || !isFinite(c.center2)) throw Error("capsule centers must be finite");
    if (!withinShapeRange(c.center1) || !withinShapeRange(c.center2)) throw Error("capsule center is more than 100000 m from the body origin");
    if (!(std::isfinite(c.radius) && c.radius > 0.0f)) throw Error("capsule radius must be finite and > 0");
    if (!withinShapeRange(c.radius)) throw Error("capsule radius is more than 100000 m");
    if (distance(c.center1, c.center2) < collide::linearSlop)
        throw Error("capsule centers are closer than the linear slop (0.005 m): use a circle");
}

namespace {

// m = ρA and I must be representable: a huge density on a large shape overflows to infinity.
void requireFiniteMass(const ShapeData::Geometry& geometry, float density) {
    MassData m;
    if (auto* c = std::get_if<Circle>(&geometry)) m = computeMass(*c, density);
    if (auto* p = std::get_if<Polygon>(&geometry)) m = computeMass(*p, density);
    if (auto* c = std::get_if<Capsule>(&geometry)) m = computeMass(*c, density);
    if (!std::isfinite(m.mass) || !std::isfinite(m.rotationalInertia) || !isFinite(m.center))
        throw Error("shape mass is not finite: density " + std::to_string(density) + " is too large for its area");
}

template <class Geometry>
ShapeId create(World::Impl& w, BodyId bodyId, const ShapeDef& def, const Geometry& geometry) {
    checkUnlocked(w.locked, "createShape");
    w.body(bodyId, "createShape");
    validate(def);
    validateGeometry(geometry);
    requireFiniteMass(geometry, def.density);
    const int index = w.addShape(bodyId, def);
    w.shapes[index].geometry = geometry;
    w.broadphase.collision.setGeometry(index, geometry);
    w.shapes[index].minExtent = w.broadphase.collision.minExtent(index);
    w.shapes[index].maxExtent = w.broadphase.collision.maxExtent(index);
    w.broadphase.createProxies(w.shapes, w.bodies, index);
    if constexpr (std::is_same_v<Geometry, Circle> || std::is_same_v<Geometry, Polygon> || std::is_same_v<Geometry, Capsule>)
        w.updateMass(bodyId.index);
    return w.shapeId(index);
}

}  // namespace

ShapeData& World::Impl::shape(ShapeId id, const char* call) {
    return const_cast<ShapeData&>(static_cast<const Impl*>(this)->shape(id, call));
}

const ShapeData& World::Impl::shape(ShapeId id, const char* call) const {
    return checkedItem(shapes, id, identity, "ShapeId", call);
}

int World::Impl::addShape(BodyId bodyId, const ShapeDef& def) {
    const int index = shapes.create();
    ShapeData& s = shapes[index];
    s.body = bodyId.index;
    s.density = def.density;
    s.friction = def.friction;
    s.restitution = def.restitution;
    s.rollingResistance = def.rollingResistance;
    s.tangentSpeed = def.tangentSpeed;
    s.sensor = def.sensor;
    s.enableContactEvents = def.enableContactEvents;
    s.enableHitEvents = def.enableHitEvents;
    shapes.anyHitEvents = shapes.anyHitEvents || def.enableHitEvents;
    shapes.noteRestitution(def.restitution);
    s.enableSensorEvents = def.enableSensorEvents;
    s.enablePreSolveEvents = def.enablePreSolveEvents;
    s.filter = def.filter;
    shapes.noteFilter(def.filter);
    s.userData = def.userData;
    bodies[bodyId.index].shapes.push_back(index);
    return index;
}

ShapeId World::createShape(BodyId body, const ShapeDef& def, const Circle& circle) { return create(*impl_, body, def, circle); }
ShapeId World::createShape(BodyId body, const ShapeDef& def, const Polygon& polygon) { return create(*impl_, body, def, polygon); }
ShapeId World::createShape(BodyId body, const ShapeDef& def, const Segment& segment) { return create(*impl_, body, def, segment); }
ShapeId World::createShape(BodyId body, const ShapeDef& def, const Chain& chain) { return create(*impl_, body, def, chain); }
ShapeId World::createShape(BodyId body, const ShapeDef& def, const Capsule& capsule) { return create(*impl_, body, def, capsule); }

void World::destroyShape(ShapeId id) {
    Impl& w = *impl_;
    checkUnlocked(w.locked, "destroyShape");
    ShapeData& s = w.shape(id);
    const int bodyIndex = s.body;
    destroyContactsOf(contactWorld(w), bodyIndex, id.index);
    w.broadphase.destroyProxies(w.shapes, id.index);
    w.broadphase.collision.clearGeometry(id.index);
    std::vector<int>& owned = w.bodies[bodyIndex].shapes;
    owned.erase(std::find(owned.begin(), owned.end(), id.index));
    w.shapes.destroy(id.index);
    w.updateMass(bodyIndex);
    wakeIsland(w.bodies, bodyIndex);
}

bool World::isValid(ShapeId id) const { return isLiveHandle(impl_->shapes, id, impl_->identity); }

std::vector<ShapeId> World::shapes(BodyId body) const {
    std::vector<ShapeId> ids;
    for (int s : impl_->body(body).shapes) ids.push_back(impl_->shapeId(s));
    return ids;
}

BodyId World::shapeBody(ShapeId id) const { return impl_->bodyId(impl_->shape(id).body); }
ShapeType World::shapeType(ShapeId id) const { return impl_->shape(id).type; }

namespace {
template <class Geometry>
const Geometry& geometryOf(const ShapeData& s, const char* name) {
    if (auto* g = std::get_if<Geometry>(&s.geometry)) return *g;
    throw Error(std::string("shape is not a ") + name);
}
}  // namespace

const Circle& World::circle(ShapeId id) const { return geometryOf<Circle>(impl_->shape(id), "circle"); }
const Polygon& World::polygon(ShapeId id) const { return geometryOf<Polygon>(impl_->shape(id), "polygon"); }
const Segment& World::segment(ShapeId id) const { return geometryOf<Segment>(impl_->shape(id), "segment"); }
const Chain& World::chain(ShapeId id) const { return geometryOf<Chain>(impl_->shape(id), "chain"); }
const Capsule& World::capsule(ShapeId id) const { return geometryOf<Capsule>(impl_->shape(id), "capsule"); }
float World::friction(ShapeId id) const { return impl_->shape(id).friction; }
float World::restitution(ShapeId id) const { return impl_->shape(id).restitution; }
float World::density(ShapeId id) const { return impl_->shape(id).density; }
bool World::isSensor(ShapeId id) const { return impl_->shape(id).sensor; }
Filter World::filter(ShapeId id) const { return impl_->shape(id).filter; }

AABB World::aabb(ShapeId id) const {
    const ShapeData& s = impl_->shape(id);
    const Transform& xf = impl_->bodies[s.body].xf;
    AABB box = impl_->broadphase.collision.computeAABB(id.index, 0, xf);
    for (int child = 1; child < impl_->broadphase.collision.childCount(id.index); ++child) {
        box = combine(box, impl_->broadphase.collision.computeAABB(id.index, child, xf));
    }
    return box;
}

// Material changes reach the shape's contacts at once (remixMaterials).
void World::setFriction(ShapeId id, float friction) {
    checkUnlocked(impl_->locked, "setFriction");
    if (!(std::isfinite(friction) && friction >= 0.0f)) throw Error("setFriction: friction must be finite and >= 0");
    impl_->shape(id).friction = friction;
    remixMaterials(impl_->contactCache, impl_->shapes, id.index);
}

void World::setRestitution(ShapeId id, float restitution) {
    checkUnlocked(impl_->locked, "setRestitution");
    if (!(std::isfinite(restitution) && restitution >= 0.0f)) throw Error("setRestitution: restitution must be finite and >= 0");
    impl_->shape(id).restitution = restitution;
    impl_->shapes.noteRestitution(restitution);
    remixMaterials(impl_->contactCache, impl_->shapes, id.index);
}

float World::rollingResistance(ShapeId id) const { return impl_->shape(id).rollingResistance; }
float World::tangentSpeed(ShapeId id) const { return impl_->shape(id).tangentSpeed; }

void World::setRollingResistance(ShapeId id, float resistance) {
    checkUnlocked(impl_->locked, "setRollingResistance");
    if (!(std::isfinite(resistance) && resistance >= 0.0f)) throw Error("setRollingResistance: resistance must be finite and >= 0");
    impl_->shape(id).rollingResistance = resistance;
    remixMaterials(impl_->contactCache, impl_->shapes, id.index);
}

void World::setTangentSpeed(ShapeId id, float speed) {
    checkUnlocked(impl_->locked, "setTangentSpeed");
    if (!std::isfinite(speed)) throw Error("setTangentSpeed: speed must be finite");
    impl_->shape(id).tangentSpeed = speed;
    remixMaterials(impl_->contactCache, impl_->shapes, id.index);
}

void World::enablePreSolveEvents(ShapeId id, bool enable) { impl_->shape(id).enablePreSolveEvents = enable; }

void World::setDensity(ShapeId id, float density) {
    checkUnlocked(impl_->locked, "setDensity");
    if (!(std::isfinite(density) && density >= 0.0f)) throw Error("setDensity: density must be finite and >= 0");
    ShapeData& s = impl_->shape(id);
    requireFiniteMass(s.geometry, density);
    s.density = density;
    impl_->updateMass(s.body);
}

}  // namespace perpdot
