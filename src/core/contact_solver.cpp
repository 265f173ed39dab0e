// Contact constraints of a step, built from the contact cache: masses, softness, anchors, effective
// masses and the approach speeds restitution reads. Their rows (the substeps' passes and, after them,
// restitution) are in contact_solver_wide.{hpp,cpp}.
#include <cstddef>

#include "core/contact_prepare.hpp"
#include "core/world_impl.hpp"

namespace perpdot {

namespace {

// The velocity a body would end the step with if nothing touched it: its state plus the substeps'
// forces still to come. Restitution reverses the approach speed at the end of the step, forces
// included: in the discrete fall a ball hits the ground with that speed, and an e = 1 bounce then
// climbs exactly as many steps as it fell (docs/stress.md). Only v and ω are set.
BodyState velocityWithoutContact(const World::Impl& w, const StepContext& ctx, int slot) {
    const BodyState& now = w.scratch.states[slot];
    const SubstepForces& f = w.scratch.substepForces[slot];
    BodyState s;
    s.v = now.v + static_cast<float>(ctx.substeps) * f.dv;
    s.w = now.w + static_cast<float>(ctx.substeps) * f.dw;
    s.invMass = now.invMass;
    return s;
}

// The contact's values of constraint c's rows, gathered field by field into `rows` (row_lanes.hpp:
// its own rows, lanes = 1, or its lane of a block), as deriveContactRows (contact_solver_wide.hpp)
// takes them: the separation in baseSeparation, last step's impulses as they were, zeros for no
// manifold point. With deriveContactRows every field is written: a reused block or slot keeps
// nothing old.
template <std::size_t lanes>
void gatherRows(const World::Impl& w, const ContactConstraint& c, RowLane<lanes> rows) {
    using Rows = ContactRows<float>;
    using PointRows = ContactPointRows<float>;
    const Contact& contact = w.contactCache.contacts[c.contact];
    rows.set(offsetof(Rows, invIA), w.scratch.inverseInertias[c.indexA]);
    rows.set(offsetof(Rows, invIB), w.scratch.inverseInertias[c.indexB]);
    rows.set(offsetof(Rows, normal), contact.normal);
    rows.set(offsetof(Rows, friction), contact.friction);
    rows.set(offsetof(Rows, restitution), contact.restitution);
    rows.set(offsetof(Rows, rollingResistance), contact.rollingResistance);
    rows.set(offsetof(Rows, tangentSpeed), contact.tangentSpeed);
    rows.set(offsetof(Rows, rollingImpulse), contact.rollingImpulse);
    rows.set(offsetof(Rows, turnsA), contact.turnsA ? 1.0f : 0.0f);
    rows.set(offsetof(Rows, turnsB), contact.turnsB ? 1.0f : 0.0f);
    for (int i = 0; i < 2; ++i) {
        const std::size_t point = offsetof(Rows, points) + static_cast<std::size_t>(i) * sizeof(PointRows);
        if (i >= contact.pointCount) {
            for (std::size_t field = 0; field < sizeof(PointRows); field += sizeof(float)) rows.set(point + field, 0.0f);
            continue;
        }
        const ContactPointState& p = contact.points[i];
        rows.set(point + offsetof(PointRows, anchorA), p.anchorA);
        rows.set(point + offsetof(PointRows, anchorB), p.anchorB);
        rows.set(point + offsetof(PointRows, baseSeparation), p.separation);
        rows.set(point + offsetof(PointRows, normalImpulse), p.normalImpulse);
        rows.set(point + offsetof(PointRows, tangentImpulse), p.tangentImpulse);
    }
}

}  // namespace

void prepareContactRows(const World::Impl& w, const StepContext& ctx, const ContactConstraint& c, ContactRows<float>& rows) {
    gatherRows<1>(w, c, {floatsOf(rows)});
    const float present[2] = {c.pointCount > 0 ? 1.0f : 0.0f, c.pointCount > 1 ? 1.0f : 0.0f};
    deriveContactRows(rows, w.scratch.freeVelocities[c.indexA], w.scratch.freeVelocities[c.indexB], present, ctx);
}

void gatherContactLane(const World::Impl& w, const ContactConstraint& c, float* lane, int lanes) {
    if (lanes == 8) gatherRows<8>(w, c, {lane});
    else gatherRows<4>(w, c, {lane});
}

// The touching contacts with an awake body, in pool order, selected by the workers: their
// contacts and bodies' solver slots. Their rows are prepared once their place is known: in a block
// (prepareContactBlocks), with the overflow or in a contact group.
void prepareContacts(World::Impl& w, const StepContext& ctx) {
    StepScratch& s = w.scratch;
    // A body is awake this step where it has a solver slot (a static one never is).
    // Contacts are not read: updateContacts left their points and bodies in dense arrays.
    const std::vector<int>& slotOf = s.bodySlots;
    const ContactCache& cache = w.contactCache;
    // Without a branch on whether a contact touches, which pool order mixes: every slot's bodies
    // are looked up (a free slot's are bodies its last contact had, still in the pool's range).
    auto constrains = [&](int index) {
        const auto [bodyA, bodyB] = cache.bodiesOf[index];
        return cache.touchingPoints[index] * (slotOf[bodyA] | slotOf[bodyB]) != 0;  // points, and a body in the solver
    };
    w.workers.parallelSelect(
        w.contactCache.contacts.capacity(), constrains,
        [&](int total) {
            s.constraints.resize(total);
            s.constraintRows.resize(total);
            s.constraintSlots.resize(total);
        },
        [&](int k, int index) {
            const auto [bodyA, bodyB] = cache.bodiesOf[index];
            ContactConstraint& c = s.constraints[k];
            c.contact = index;
            c.indexA = slotOf[bodyA];
            c.indexB = slotOf[bodyB];
            c.pointCount = cache.touchingPoints[index];
            s.constraintSlots[k] = {c.indexA, c.indexB};
        });
    s.freeVelocities.resize(s.states.size());
    w.workers.parallelFor(static_cast<int>(s.states.size()), 256, [&](int begin, int end, int) {
        for (int slot = begin; slot < end; ++slot) s.freeVelocities[slot] = velocityWithoutContact(w, ctx, slot);
    });
    findContactGroups(w, ctx);
    prepareContactBlocks(w, ctx);
}

}  // namespace perpdot
