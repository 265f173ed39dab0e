// Re-fit ahead: the broadphase tree follows the bodies on a worker of its own while the others
// prepare and solve the step, as Box2D v3 rebuilds its tree beside its narrowphase. A tree re-fit
// (b2DynamicTree::MoveProxy: remove, insert, rebalance) is serial work, and neither preparing nor
// solving reads the tree; so the re-fits are made early, at each body's end pose predicted from
// its velocity after the forces of integrateVelocities (c + h v, θ + h ω), and finalizeBodies
// re-fits only what the prediction missed (a body the solver turned). Which proxies re-fit, to
// which boxes and in which order, depends on the world alone: the tree is the same for any worker
// count. The task does tree work only where it can: a body of one proxy (most) has its new fat
// AABB and box room found by the workers that predict the poses, and the task moves its leaf.
//
// A proxy re-fits when its box sticks out of its fat AABB, as in Box2D v3; a fat AABB grown large
// by a fast move is not shrunk when the body slows (Box2D 2.4's "huge" test) — it is at most two
// margins longer along the motion (collision.cpp). Whether a body's boxes are inside is known
// without computing them while it strays less from where they were last measured than they had
// room (box_room.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/world/stages.hpp"

namespace perpdot {

namespace {

// The room a box has inside its proxy's fat AABB under and over it, folded into (below, above).
void foldRoom(Vec2& below, Vec2& above, const AABB& box, const AABB& fat) {
    below = {std::min(below.x, box.lower.x - fat.lower.x), std::min(below.y, box.lower.y - fat.lower.y)};
    above = {std::min(above.x, fat.upper.x - box.upper.x), std::min(above.y, fat.upper.y - box.upper.y)};
}

// The room measured at pose (center, q) into the box room; whether every box was inside.
bool rememberRoom(BoxRoom& known, Vec2 center, Rot q, Vec2 below, Vec2 above) {
    const bool inside = std::min(std::min(below.x, below.y), std::min(above.x, above.y)) >= 0.0f;
    known.center = center;
    known.q = q;
    known.below = inside ? below : Vec2{-1.0f, -1.0f};  // else measured again once re-fitted
    known.above = above;
    return inside;
}

constexpr float most = std::numeric_limits<float>::max();

}  // namespace

BoxRoom& knownShapes(Broadphase& broadphase, const Pool<Body>& bodies, const ShapeStore& shapes, int body) {
    BoxRoom& known = broadphase.boxRooms[body];
    if (known.reach >= 0.0f) return known;
    // Forgotten: the shapes or the centre of mass changed.
    const Body& b = bodies[body];
    known.reach = 0.0f;
    float minExtent = most, maxExtent = 0.0f;
    for (int s : b.shapes) {
        known.reach = std::max(known.reach, broadphase.collision.turningReach(s, b.localCenter));
        if (!sweeps(shapes[s])) continue;
        minExtent = std::min(minExtent, shapes[s].minExtent);
        maxExtent = std::max(maxExtent, shapes[s].maxExtent);
    }
    known.fastTravel = maxExtent > 0.0f ? safetyFactor * minExtent : std::numeric_limits<float>::infinity();
    known.sweepRadius = maxExtent + length(b.localCenter);
    return known;
}

namespace {

// A body's one proxy and its box at a pose (-1: the body has more, or none was measured).
struct SoleBox {
    int proxy = -1;
    AABB box;
};

// The body's boxes at pose xf against their fat AABBs, into its box room; with `refitAlong`, the
// boxes that stick out are re-fitted first (grown along that displacement). Whether all were inside.
// A body of one proxy leaves it and its box in `sole` (when given): its re-fit needs no second look.
bool measureBoxes(Broadphase& broadphase, const Pool<Body>& bodies, const ShapeStore& shapes, int body, Vec2 center,
                  const Transform& xf, const Vec2* refitAlong, SoleBox* sole = nullptr) {
    BoxRoom& known = knownShapes(broadphase, bodies, shapes, body);
    const Body& b = bodies[body];
    Vec2 below{most, most}, above{most, most};
    for (int s : b.shapes) {
        const std::vector<int>& proxies = shapes[s].proxies;
        for (int child = 0; child < static_cast<int>(proxies.size()); ++child) {
            const AABB box = broadphase.collision.computeAABB(s, child, xf);
            if (refitAlong != nullptr && broadphase.collision.room(proxies[child], box) < 0.0f) broadphase.refitProxy(proxies[child], box, *refitAlong);
            foldRoom(below, above, box, broadphase.collision.fatAABB(proxies[child]));
            if (sole != nullptr) *sole = {b.shapes.size() == 1 && proxies.size() == 1 ? proxies[0] : -1, box};
        }
    }
    return rememberRoom(known, center, xf.q, below, above);
}

// A body of one proxy whose box `sole` escaped: where its leaf moves in place, its new fat AABB and
// the box room that leaves are found here, by the workers that predicted the poses (the
// CollisionSystem reads only); the re-fit task then moves the leaf.
void planInPlaceMove(Broadphase& broadphase, int body, PredictedPose& p, const SoleBox& sole) {
    p.inPlace.proxy = -1;
    if (sole.proxy < 0) return;
    const std::optional<AABB> fat = broadphase.collision.inPlaceFat(sole.proxy, sole.box, p.displacement);
    if (!fat) return;
    Vec2 below{most, most}, above{most, most};
    foldRoom(below, above, sole.box, *fat);
    rememberRoom(broadphase.boxRooms[body], p.center, p.xf.q, below, above);
    p.inPlace = {sole.proxy, *fat};
}

// The re-fits, in awake-body order: the planned moves in place, and the other bodies' boxes
// measured and re-fitted as measureBoxes does. First, the contacts found apart are released:
// serial work too, which nothing reads before the next pair update.
void refitPredicted(int, int, int, void* world) {
    const RefitWorld& w = *static_cast<const RefitWorld*>(world);
    releaseApartContacts(w.contactCache);
    const std::vector<PredictedPose>& poses = w.scratch.bodies.predictedPoses;
    for (size_t k = 0; k < poses.size(); ++k) {
        const PredictedPose& p = poses[k];
        if (!p.refit) continue;
        if (p.inPlace.proxy >= 0) w.broadphase.moveInPlace(p.inPlace.proxy, p.inPlace.fat);
        else refitEscaped(w.broadphase, w.bodies, w.shapes, w.scratch.bodies.awakeBodies[k], p.center, p.xf, p.displacement);
    }
    // A worn tree is built anew here too, beside the solver rather than before the next queries.
    w.broadphase.collision.rebuildTreeIfWorn();
}

}  // namespace

bool boxesInside(Broadphase& broadphase, const Pool<Body>& bodies, const ShapeStore& shapes, int body, Vec2 center,
                 const Transform& xf) {
    return broadphase.boxRooms[body].holds(center, xf.q) || measureBoxes(broadphase, bodies, shapes, body, center, xf, nullptr);
}

void refitEscaped(Broadphase& broadphase, const Pool<Body>& bodies, const ShapeStore& shapes, int body, Vec2 center,
                  const Transform& xf, Vec2 displacement) {
    measureBoxes(broadphase, bodies, shapes, body, center, xf, &displacement);
}

void startTreeRefit(RefitWorld& w, const StepContext& ctx) {
    // The parts the loop reads, bound once: through the view each is one load further.
    Broadphase& broadphase = w.broadphase;
    const Pool<Body>& bodies = w.bodies;
    const ShapeStore& shapes = w.shapes;
    SolverBodies& solverBodies = w.scratch.bodies;
    const int count = static_cast<int>(solverBodies.awakeBodies.size());
    solverBodies.predictedPoses.resize(static_cast<size_t>(count));
    broadphase.boxRooms.resize(static_cast<size_t>(bodies.capacity()));
    w.workers.parallelFor(count, 256, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int index = solverBodies.awakeBodies[k];
            const Body& b = bodies[index];
            const BodyState& s = solverBodies.states[k + 1];
            PredictedPose& p = solverBodies.predictedPoses[k];
            p.displacement = ctx.h * s.v;
            const float turn = ctx.h * s.w;
            p.refit = false;
            if (!isFinite(p.displacement) || !std::isfinite(turn)) continue;
            const Rot q = integrateRotation(b.xf.q, turn);  // R(θ + hω), to first order: a prediction
            p.center = b.center + p.displacement;
            p.xf = {p.center - rotate(q, b.localCenter), q};
            // A huge but finite speed (a restored snapshot's, before the solver clamps it) can
            // overflow the prediction: no box is made of it, the real end pose decides.
            if (!isFinite(p.xf.p) || !std::isfinite(q.c) || !std::isfinite(q.s)) continue;
            // A body without shapes is never measured, so its box room never holds: its shape list
            // (the body's last cache line) is read only then.
            SoleBox sole;
            p.refit = !broadphase.boxRooms[index].holds(p.center, p.xf.q) && !b.shapes.empty() &&
                      !measureBoxes(broadphase, bodies, shapes, index, p.center, p.xf, nullptr, &sole);
            if (p.refit) planInPlaceMove(broadphase, index, p, sole);
        }
    });
    w.workers.runAside(&refitPredicted, &w);
}

void finishTreeRefit(Workers& workers) { workers.awaitAside(); }

}  // namespace perpdot
