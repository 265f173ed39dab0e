// Re-fit ahead: the broadphase tree follows the bodies on a worker of its own while the others
// prepare and solve the step, as Box2D v3 rebuilds its tree beside its narrowphase. A tree re-fit
// (b2DynamicTree::MoveProxy: remove, insert, rebalance) is serial work, and neither preparing nor
// solving reads the tree; so the re-fits are made early, at each body's end pose predicted from
// its velocity after the forces of integrateVelocities (c + h v, θ + h ω), and finalizeBodies
// re-fits only what the prediction missed (a body the solver turned). Which proxies re-fit, to
// which boxes and in which order, depends on the world alone: the tree is the same for any worker
// count.
//
// The prediction also spares finalizeBodies most of its checks: a body whose every shape point
// ends within `room` of where the predicted pose put it still has its boxes inside their fat
// AABBs. A point at ℓ from the centre of mass moves by Δc + (q₁ − q₀)ℓ between two poses (q as
// the complex number c + i s), so by at most |Δc| + |q₁ − q₀|·reach.
#include <algorithm>
#include <cmath>

#include "core/stages.hpp"

namespace perpdot {

namespace {

// The re-fits, in awake-body order.
void refitPredicted(int, int, int, void* world) {
    World::Impl& w = *static_cast<World::Impl*>(world);
    const std::vector<PredictedPose>& poses = w.scratch.predictedPoses;
    for (size_t k = 0; k < poses.size(); ++k)
        if (poses[k].refit) w.synchronizeProxies(w.scratch.awakeBodies[k], poses[k].xf, poses[k].displacement);
}

}  // namespace

void startTreeRefit(World::Impl& w, const StepContext& ctx) {
    const int count = static_cast<int>(w.scratch.awakeBodies.size());
    w.scratch.predictedPoses.resize(static_cast<size_t>(count));
    w.workers.parallelFor(count, 256, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            const int index = w.scratch.awakeBodies[k];
            const Body& b = w.bodies[index];
            const BodyState& s = w.scratch.states[k + 1];
            PredictedPose& p = w.scratch.predictedPoses[k];
            p.displacement = ctx.h * s.v;
            const float turn = ctx.h * s.w;
            p.refit = false;
            p.room = -1.0f;
            if (b.shapes.empty() || !isFinite(p.displacement) || !std::isfinite(turn)) continue;
            const Rot q = integrateRotation(b.xf.q, turn);  // R(θ + hω), to first order: a prediction
            p.center = b.center + p.displacement;
            p.xf = {p.center - rotate(q, b.localCenter), q};
            const World::Impl::ProxyRoom r = w.proxyRoom(index, p.xf, p.displacement);
            p.refit = !r.keep;
            p.reach = r.reach + length(b.localCenter);
            p.room = r.room;
        }
    });
    w.workers.runAside(&refitPredicted, &w);
}

void finishTreeRefit(World::Impl& w) { w.workers.awaitAside(); }

bool staysInside(const PredictedPose& p, Vec2 center, Rot q) {
    // |Δc| + |q₁ − q₀|·reach, bounded by the sums of the components' sizes.
    const float stray = std::fabs(center.x - p.center.x) + std::fabs(center.y - p.center.y) +
                        p.reach * (std::fabs(q.c - p.xf.q.c) + std::fabs(q.s - p.xf.q.s));
    const float rounding = 1e-5f * (1.0f + std::fabs(center.x) + std::fabs(center.y) + p.reach);
    return stray + rounding <= p.room;
}

}  // namespace perpdot
