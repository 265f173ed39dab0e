// The character mover (perpdot/mover.hpp): an upright capsule moved by collide-and-slide.
//
// Each move: (1) the capsule is pushed out of anything that moved into it and takes the impulse
// dynamic bodies gave its kinematic body, (2) it rides the platform under it by that platform's
// point velocity, (3) it walks along the ground tangent or falls under gravity, sliding along the
// planes it meets (steep slopes are vertical walls to a walker), climbing steps, (4) it probes for
// ground below, snapping down when it was grounded. Its body is then placed at the new position.
//
// Casts are conservative advancement (collide::conservativeAdvance, shared with the time of impact)
// on b2Distance (CollisionSystem::coreDistance): the surface gap g(t) between a convex capsule
// translated by t·D and a convex shape is a convex function of t, so it lies above its tangent,
// and stepping t by (g − skin)/(−g′) never passes the contact.
#include <algorithm>
#include <cmath>

#include "collide/time_of_impact.hpp"
#include "core/queries/query_world.hpp"
#include "perpdot/portable_math.hpp"

namespace perpdot {

namespace {

constexpr int maxCastIterations = 20;
constexpr float minMove = 1.0e-6f;  // m: shorter displacements are not cast
constexpr float parallel = 1.0e-3f; // moving within ~0.06° of a surface's tangent is sliding along it

struct Hit {
    bool hit = false;
    float fraction = 1.0f;
    Vec2 normal;  // from the surface to the capsule
    Vec2 point;
    int shape = -1;
};

// The surface gap between the capsule centred at `center` and one shape child, with the normal
// from that shape to the capsule; invalid when the cores overlap (no direction).
struct Gap {
    bool valid = false;
    float gap = 0.0f;
    Vec2 normal;
    Vec2 point;
};

class MoverSolver {
public:
    MoverSolver(World& world, const QueryWorld& w, const MoverDef& def, const MoverState& s)
        : w_(w), world_(world), def_(def), body_(s.body.index), shape_(s.shape.index), cosMaxSlope_(sinCos(def.maxSlope).cos) {}

    bool walkable(Vec2 normal) const { return normal.y >= cosMaxSlope_; }

    Gap gap(Vec2 center, collide::ChildKey other) const {
        const collide::CoreDistance d =
            w_.collision.coreDistance({shape_, 0}, Transform{center, Rot{}}, other, w_.bodies[w_.shapes[other.shape].body].xf);
        if (d.distance <= 0.0f) return {};
        const Vec2 n = (1.0f / d.distance) * (d.pointA - d.pointB);
        return {true, d.distance - d.radiusA - d.radiusB, n, d.pointB + d.radiusB * n};
    }

    // Calls visit(key) for every solid child near `box` that the capsule collides with.
    template <class Visit>
    void forEachNear(const AABB& box, Visit&& visit) const {
        w_.collision.query(box, [&](int proxy) {
            const collide::ChildKey key = w_.collision.proxyKey(proxy);
            const ShapeData& s = w_.shapes[key.shape];
            if (s.body != body_ && !s.sensor && shouldCollide(def_.filter, s.filter)) visit(key);
            return true;
        });
    }

    bool oneWay(int shape) const { return (w_.shapes[shape].filter.category & def_.oneWayCategories) != 0; }

    AABB bounds(Vec2 center, Vec2 translation, float margin) const {
        const Vec2 half{def_.radius + margin, def_.halfHeight + def_.radius + margin};
        const Vec2 end = center + translation;
        return {Vec2{std::min(center.x, end.x), std::min(center.y, end.y)} - half,
                Vec2{std::max(center.x, end.x), std::max(center.y, end.y)} + half};
    }

    // Earliest fraction of `translation` at which the capsule comes within the skin of a surface.
    Hit cast(Vec2 start, Vec2 translation) const {
        Hit best;
        if (length(translation) < minMove) return best;
        const float tolerance = 0.1f * def_.skin;
        forEachNear(bounds(start, translation, 2.0f * def_.skin), [&](collide::ChildKey key) {
            const bool fromAboveOnly = oneWay(key.shape);
            if (fromAboveOnly && translation.y >= 0.0f) return;
            Gap last;
            const collide::Advanced advanced = collide::conservativeAdvance(
                [&](float t, int iteration) {
                    last = gap(start + t * translation, key);
                    if (!last.valid) return collide::Advance{.stop = true};  // cores overlap: recovery's business
                    // A one-way shape counts only when met from above, the capsule not already in it.
                    if (fromAboveOnly && (!walkable(last.normal) || (iteration == 0 && last.gap < def_.skin - tolerance)))
                        return collide::Advance{.stop = true};
                    const float approach = -dot(translation, last.normal);  // −g′(t)
                    // Moving along the surface (or away), even within the skin: g never falls again (convex).
                    if (approach <= parallel * length(translation)) return collide::Advance{.stop = true};
                    return collide::Advance{.gap = last.gap - def_.skin, .closingSpeed = approach};
                },
                tolerance, best.fraction, maxCastIterations);
            if (advanced.outcome == collide::Advanced::Contact && (!best.hit || advanced.t < best.fraction))
                best = {true, advanced.t, last.normal, last.point, key.shape};
        });
        return best;
    }

    // Push out of surfaces closer than the skin (things that moved into the capsule); returns the
    // push.
    Vec2 recover(Vec2 center) const {
        Vec2 push;
        for (int pass = 0; pass < def_.maxIterations; ++pass) {
            Vec2 step;
            forEachNear(bounds(center + push, {}, def_.skin), [&](collide::ChildKey key) {
                const Gap g = gap(center + push, key);
                if (!g.valid || g.gap >= def_.skin) return;
                // One-way shapes push up only, and only when the capsule is mostly above them.
                if (oneWay(key.shape) && (!walkable(g.normal) || g.gap < -0.5f * def_.radius)) return;
                const float depth = def_.skin - g.gap;
                if (dot(step, g.normal) < depth) step += (depth - std::max(0.0f, dot(step, g.normal))) * g.normal;
            });
            if (lengthSquared(step) == 0.0f) break;
            push += step;
        }
        return push;
    }

    // Gives a dynamic body it walks into the momentum to match the capsule's speed along the
    // normal, capped by maxPushForce.
    void pushBody(const Hit& hit, Vec2 velocity, float dt) const {
        const int index = w_.shapes[hit.shape].body;
        const Body& b = w_.bodies[index];
        if (b.type != BodyType::Dynamic) return;
        const Vec2 r = hit.point - b.center;
        const float closing = dot(velocity - (b.v + b.w * perp(r)), -1.0f * hit.normal);
        if (closing <= 0.0f) return;
        const float impulse = std::min(b.mass * closing, def_.maxPushForce * dt);
        const Vec2 j = -impulse * hit.normal;
        world_.applyLinearImpulse(w_.bodyId(index), j, hit.point);  // v += j/m, ω += perpDot(r, j)/I
    }

    // Whether a ray from the bottom of the feet straight down meets walkable ground within `reach`:
    // a capsule resting on an edge has a steep contact normal, yet stands on the step it is over.
    bool walkableBelow(Vec2 center, float reach) const {
        const Vec2 p1 = center - Vec2{0.0f, def_.halfHeight + def_.radius - def_.skin};
        const Vec2 p2 = p1 - Vec2{0.0f, reach + 2.0f * def_.skin};
        bool found = false;
        w_.collision.rayCastTree(p1, p2, [&](int proxy, float maxFraction) {
            const collide::ChildKey key = w_.collision.proxyKey(proxy);
            const ShapeData& s = w_.shapes[key.shape];
            if (s.body == body_ || s.sensor || !shouldCollide(def_.filter, s.filter)) return -1.0f;
            collide::RayCastResult result;
            if (!w_.collision.rayCast(key, w_.bodies[s.body].xf, p1, p2, maxFraction, result)) return -1.0f;
            found = walkable(result.normal);
            return result.fraction;
        });
        return found;
    }

    // Ground under a downward cast's hit: a walkable surface, or an edge over walkable ground.
    bool standsOn(const Hit& hit, Vec2 center, float reach) const {
        return hit.hit && (walkable(hit.normal) || walkableBelow(center, reach));
    }

    // Landing on a step: an edge counts only with walkable ground right under the feet (a cap's
    // depth below the edge), not the floor the step stands on.
    bool landsOn(const Hit& hit, Vec2 center, float drop) const {
        return hit.hit && (walkable(hit.normal) || walkableBelow(center, hit.fraction * drop + def_.radius * (1.0f - cosMaxSlope_)));
    }

    // Climb a step: up by stepHeight, forward by `forward` (at least a radius, so the feet clear
    // the edge in one stride), down onto walkable ground.
    bool stepUp(Vec2& center, Vec2 forward) const {
        if (std::fabs(forward.x) < def_.radius) forward.x = std::copysign(def_.radius, forward.x);
        const Vec2 up{0.0f, def_.stepHeight};
        const Hit rise = cast(center, up);
        Vec2 p = center + rise.fraction * up;
        const Hit ahead = cast(p, forward);
        if (ahead.fraction * length(forward) < minMove) return false;
        p += ahead.fraction * forward;
        const Vec2 down{0.0f, -(rise.fraction * def_.stepHeight + 2.0f * def_.skin)};
        const Hit land = cast(p, down);
        if (!landsOn(land, p, -down.y)) return false;
        center = p + land.fraction * down;
        return true;
    }

    // Collide-and-slide of `displacement`; clips `velocity` against the planes met.
    void slide(MoverState& s, Vec2 displacement, Vec2& velocity, bool grounded, bool climb, float dt) const {
        Vec2 remaining = displacement;
        Vec2 previous;
        bool stepped = false;
        for (int i = 0; i < def_.maxIterations && length(remaining) > minMove; ++i) {
            const Hit hit = cast(s.position, remaining);
            s.position += hit.fraction * remaining;
            if (!hit.hit) return;
            remaining = (1.0f - hit.fraction) * remaining;
            pushBody(hit, velocity, dt);
            Vec2 n = hit.normal;
            if (!walkable(n) && grounded) {
                const Vec2 forward{remaining.x, 0.0f};
                if (climb && !stepped && std::fabs(forward.x) > minMove && stepUp(s.position, forward)) {
                    stepped = true;
                    remaining = {};
                    break;
                }
                // A walker meets steep slopes as vertical walls: it must not climb them.
                if (std::fabs(n.x) > 0.0f && n.y > 0.0f) n = normalize(Vec2{n.x, 0.0f});
            }
            if (const float into = dot(remaining, n); into < 0.0f) remaining -= into * n;
            if (const float into = dot(velocity, n); into < 0.0f) velocity -= into * n;
            // Two planes met in turn pin the capsule in their crease (2D: nowhere left to slide).
            // (A curved surface met twice is one plane turning, not a crease.)
            if (lengthSquared(previous) > 0.0f && dot(n, previous) < 0.99f && dot(remaining, previous) < 0.0f) return;
            previous = n;
        }
    }

    // Ground below the feet within `reach`: snaps down to it when `snap`.
    void probeGround(MoverState& s, float reach, bool snap) const {
        const Vec2 down{0.0f, -reach};
        const Hit hit = cast(s.position, down);
        s.grounded = standsOn(hit, s.position, reach) && (snap || hit.fraction * reach <= 2.0f * def_.skin);
        if (!s.grounded) {
            s.ground = {};
            return;
        }
        s.position += hit.fraction * down;
        s.groundNormal = walkable(hit.normal) ? hit.normal : Vec2{0.0f, 1.0f};  // on an edge: level
        s.ground = w_.shapeId(hit.shape);
    }

    // The impulse dynamic bodies put on the capsule's body in the last step, over the mover's mass.
    Vec2 pushedVelocity() const {
        Vec2 impulse;
        const ContactCache& cache = w_.contactCache;
        cache.bodyLists.forEach(cache.contacts, body_, [&](int contact, int onB) {
            const Contact& c = cache.contacts[contact];
            const float side = onB ? 1.0f : -1.0f;  // normal runs from A to B
            if (c.touching && w_.bodies[onB ? c.bodyA : c.bodyB].type == BodyType::Dynamic)
                for (int p = 0; p < c.pointCount; ++p) impulse += (side * c.points[p].normalImpulse) * c.normal;
        });
        return (1.0f / def_.mass) * impulse;
    }

private:
    const QueryWorld w_;
    World& world_;  // pushes bodies through its calls
    const MoverDef& def_;
    int body_, shape_;
    float cosMaxSlope_;
};

void requirePositive(float value, const char* name) {
    if (!(std::isfinite(value) && value > 0.0f)) throw Error(std::string("MoverDef.") + name + " must be finite and > 0");
}

void requireNonNegative(float value, const char* name) {
    if (!(std::isfinite(value) && value >= 0.0f)) throw Error(std::string("MoverDef.") + name + " must be finite and >= 0");
}

}  // namespace

void validate(const MoverDef& def) {
    requirePositive(def.radius, "radius");
    requirePositive(def.halfHeight, "halfHeight");
    requirePositive(def.skin, "skin");
    requirePositive(def.mass, "mass");
    requireNonNegative(def.stepHeight, "stepHeight");
    requireNonNegative(def.snapDistance, "snapDistance");
    requireNonNegative(def.jumpSpeed, "jumpSpeed");
    requireNonNegative(def.maxPushForce, "maxPushForce");
    requireNonNegative(def.pushDamping, "pushDamping");
    if (!(def.maxSlope > 0.0f && def.maxSlope < 0.5f * pi)) throw Error("MoverDef.maxSlope must be in (0, π/2) radians");
    if (def.maxIterations < 1 || def.maxIterations > 32) throw Error("MoverDef.maxIterations must be in 1..32");
    if (def.stepHeight >= def.halfHeight + def.radius) throw Error("MoverDef.stepHeight must be below the capsule's half height + radius");
}

MoverState World::createMover(const MoverDef& def, Vec2 position) {
    validate(def);
    if (!isFinite(position)) throw Error("createMover: position must be finite");
    MoverState s;
    s.position = position;
    s.body = createBody({.type = BodyType::Kinematic, .position = position, .allowSleep = false});
    s.shape = createShape(s.body, {.density = 0.0f, .filter = def.filter},
                          Capsule{{0.0f, -def.halfHeight}, {0.0f, def.halfHeight}, def.radius});
    return s;
}

void World::moveMover(const MoverDef& def, MoverState& s, const MoverInput& input, float dt) {
    const QueryWorld w = queryWorld(*impl_);
    checkUnlocked(w.locked, "moveMover");
    validate(def);
    if (!(std::isfinite(dt) && dt > 0.0f)) throw Error("moveMover: dt must be finite and > 0");
    if (!std::isfinite(input.walkSpeed)) throw Error("moveMover: walkSpeed must be finite");
    if (shapeBody(s.shape) != s.body) throw Error("moveMover: state's shape is not on its body");
    const MoverSolver solver(*this, w, def, s);
    const Vec2 start = s.position;
    const bool wasGrounded = s.grounded;

    // (1) Being pushed: out of what moved in, and the momentum dynamic bodies gave the body.
    s.position += solver.recover(s.position);
    s.pushVelocity += solver.pushedVelocity();
    if (wasGrounded) s.pushVelocity = exp(-def.pushDamping * dt) * s.pushVelocity;

    // (2) Ride the platform: its point velocity under the feet over the step that just moved it.
    if (wasGrounded && isValid(s.ground)) {
        const BodyId platform = shapeBody(s.ground);
        if (bodyType(platform) != BodyType::Static) {
            Vec2 carried = pointVelocity(platform, s.position - Vec2{0.0f, def.halfHeight + def.radius});
            solver.slide(s, dt * carried, carried, false, false, dt);
        }
    }

    // (3) Walk along the ground tangent, or fall; jump from the ground.
    const Vec2 gravity = settings().gravity;
    if (wasGrounded && input.jump) {
        s.velocity = {input.walkSpeed, def.jumpSpeed};
        s.grounded = false;
    } else if (wasGrounded) {
        const Vec2 tangent{s.groundNormal.y, -s.groundNormal.x};
        s.velocity = input.walkSpeed * tangent;
    } else {
        s.velocity = {input.walkSpeed, s.velocity.y + dt * gravity.y};
    }
    Vec2 velocity = s.velocity + s.pushVelocity;
    solver.slide(s, dt * velocity, velocity, s.grounded, true, dt);
    s.velocity.y = std::min(s.velocity.y, velocity.y - s.pushVelocity.y);  // ceilings and landings stop it
    if (velocity.y == 0.0f) s.pushVelocity.y = 0.0f;

    // (4) Ground: snap down when it was grounded and did not jump (walking uphill moves up too),
    // else look just below the feet unless rising.
    if (s.grounded || s.velocity.y <= 0.0f) {
        solver.probeGround(s, s.grounded ? def.snapDistance : 2.0f * def.skin, s.grounded);
        if (s.grounded) s.velocity.y = 0.0f;
    } else {
        s.grounded = false;
        s.ground = {};
    }

    s.lastDisplacement = s.position - start;
    setTransform(s.body, s.position, 0.0f);
    setLinearVelocity(s.body, {});
}

}  // namespace perpdot
