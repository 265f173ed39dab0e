// Contact constraints of a step, built from the contact cache: masses, softness, anchors, effective
// masses and the approach speeds restitution reads. Their rows (the substeps' passes and, after them,
// restitution) are in contact_solver_wide.{hpp,cpp}.
#include <cstddef>
#include <cstring>
#include <span>

#include "core/solver/contact_prepare.hpp"
#include "core/solver/contact_solver.hpp"
#include "core/solver/impact_propagation.hpp"
#include "core/solver/support_sinks.hpp"

namespace perpdot {

namespace {

// The velocity a body would end the step with if nothing touched it: its state plus the substeps'
// forces still to come. Restitution reverses the approach speed at the end of the step, forces
// included: in the discrete fall a ball hits the ground with that speed, and an e = 1 bounce then
// climbs exactly as many steps as it fell (docs/stress.md). Only v and ω are set.
BodyState velocityWithoutContact(const SolverWorld& w, const StepContext& ctx, int slot) {
    const BodyState& now = w.scratch.bodies.states[slot];
    const SubstepForces& f = w.scratch.bodies.substepForces[slot];
    BodyState s;
    s.v = now.v + static_cast<float>(ctx.substeps) * f.dv;
    s.w = now.w + static_cast<float>(ctx.substeps) * f.dw;
    s.invMass = now.invMass;
    return s;
}

// The value of a Solver field (SolverValue, contact_solver_wide.hpp) for constraint c of `contact`;
// inverseInertias: the bodies' 1/I by solver slot.
template <SolverValue value>
float solverFieldValue(std::span<const float> inverseInertias, const ContactConstraint& c, const Contact& contact) {
    if constexpr (value == SolverValue::InverseInertiaA) {
        return inverseInertias[c.indexA];
    } else if constexpr (value == SolverValue::InverseInertiaB) {
        return inverseInertias[c.indexB];
    } else if constexpr (value == SolverValue::TurnsA) {
        return contact.turnsA ? 1.0f : 0.0f;
    } else {
        static_assert(value == SolverValue::TurnsB, "a SolverValue needs its case in solverFieldValue");
        return contact.turnsB ? 1.0f : 0.0f;
    }
}

// The Solver fields of contactRowFields (solverRowFields) of a block's `used` lanes, `lanes` wide.
template <std::size_t lanes>
void gatherOtherFields(std::span<const float> inverseInertias, const ContactConstraint* const (&constraints)[lanes],
                       const Contact* const (&contacts)[lanes], int used, float* rows) {
    for (int lane = 0; lane < used; ++lane) {
        const RowLane<lanes> at{rows + lane};
        forEachRowField<solverRowFields>([&](auto field) {
            constexpr ContactRowField f = decltype(field)::value;
            at.set(f.row, solverFieldValue<f.solverValue>(inverseInertias, *constraints[lane], *contacts[lane]));
        });
    }
}

// One constraint's rows from its contact, as deriveContactRows (contact_solver_wide.hpp) takes
// them: the fields of its two runs of floats where a block's gather puts them (contactRunFields,
// pointRunFields: the separation in baseSeparation, last step's impulses as they were, zeros for
// no manifold point), and the others (gatherOtherFields). With deriveContactRows every field is
// written: a reused slot keeps nothing old.
void gatherRows(const SolverWorld& w, const ContactConstraint& c, ContactRows<float>& out) {
    using Rows = ContactRows<float>;
    using PointRows = ContactPointRows<float>;
    float* rows = floatsOf(out);
    const Contact& contact = w.contactCache.contacts[c.contact];
    const auto* bytes = reinterpret_cast<const char*>(&contact);
    float run[8];
    std::memcpy(run, bytes + offsetof(Contact, friction), sizeof run);
    for (std::size_t f = 0; f < 7; ++f) rows[contactRunFields[f] / sizeof(float)] = run[f];
    for (std::size_t i = 0; i < 2; ++i) {
        std::memcpy(run, bytes + offsetof(Contact, points) + i * sizeof(ContactPointState), sizeof run);
        const bool point = static_cast<int>(i) < contact.pointCount;
        for (std::size_t f = 0; f < 7; ++f) rows[(offsetof(Rows, points) + i * sizeof(PointRows) + pointRunFields[f]) / sizeof(float)] = point ? run[f] : 0.0f;
    }
    const ContactConstraint* const constraints[1] = {&c};
    const Contact* const contacts[1] = {&contact};
    gatherOtherFields(w.scratch.bodies.inverseInertias, constraints, contacts, 1, rows);
}

}  // namespace

void prepareContactRows(const SolverWorld& w, const StepContext& ctx, const ContactConstraint& c, ContactRows<float>& rows) {
    gatherRows(w, c, rows);
    const float present[2] = {c.pointCount > 0 ? 1.0f : 0.0f, c.pointCount > 1 ? 1.0f : 0.0f};
    deriveContactRows(rows, w.scratch.bodies.freeVelocities[c.indexA], w.scratch.bodies.freeVelocities[c.indexB], present, ctx);
}

namespace {

// The lanes' contacts, or for an empty lane a contact of zeros.
template <std::size_t lanes>
void laneContacts(const SolverWorld& w, const ContactConstraint* const (&constraints)[lanes], int used, const Contact* (&contacts)[lanes]) {
    static const Contact none{};
    for (std::size_t lane = 0; lane < lanes; ++lane)
        contacts[lane] = static_cast<int>(lane) < used ? &w.contactCache.contacts[constraints[lane]->contact] : &none;
}

// The runs of a block's contacts into its lanes: gatherContactRuns at four lanes, in the AVX2 file at eight.
void gatherRuns(ContactBlock<4>& block, const float* const (&head)[4], const float* const (&points)[2][4], const float (&present)[2][4]) {
    gatherContactRuns<simd::Float4>(block, head, points, present);
}
#ifdef PERPDOT_AVX2
void gatherRuns(ContactBlock<8>& block, const float* const (&head)[8], const float* const (&points)[2][8], const float (&present)[2][8]) {
    gatherContactRows8(block, head, points, present);
}
#endif

template <std::size_t lanes>
void gatherLanes(const SolverWorld& w, const ContactConstraint* const (&constraints)[lanes], int used, ContactBlock<lanes>& block,
                 const float (&present)[2][lanes]) {
    const Contact* contacts[lanes];
    laneContacts(w, constraints, used, contacts);
    const float* head[lanes];
    const float* points[2][lanes];
    for (std::size_t lane = 0; lane < lanes; ++lane) {
        head[lane] = &contacts[lane]->friction;
        for (int i = 0; i < 2; ++i) points[i][lane] = &contacts[lane]->points[i].anchorA.x;
    }
    gatherRuns(block, head, points, present);
    gatherOtherFields(w.scratch.bodies.inverseInertias, constraints, contacts, used, block.rows.data);
}

}  // namespace

void gatherContactLanes(const SolverWorld& w, const ContactConstraint* const (&constraints)[4], int used, ContactBlock<4>& block,
                        const float (&present)[2][4]) {
    gatherLanes(w, constraints, used, block, present);
}

#ifdef PERPDOT_AVX2
void gatherContactLanes(const SolverWorld& w, const ContactConstraint* const (&constraints)[8], int used, ContactBlock<8>& block,
                        const float (&present)[2][8]) {
    gatherLanes(w, constraints, used, block, present);
}
#endif

// The touching contacts with an awake body, in pool order, selected by the workers: their
// contacts and bodies' solver slots. Their rows are prepared once their place is known: in a block
// (prepareContactBlocks), with the overflow or in a contact group.
void selectContacts(const SolverWorld& w, const StepContext& ctx) {
    const SolverWorld::Scratch& s = w.scratch;
    // A body is awake this step where it has a solver slot (a static one never is).
    // Contacts are not read: updateContacts left their points and bodies in dense arrays.
    const std::vector<int>& slotOf = s.bodies.bodySlots;
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
            s.contacts.constraints.resize(total);
            s.contacts.constraintRows.resize(total);
            s.contacts.constraintSlots.resize(total);
        },
        [&](int k, int index) {
            const auto [bodyA, bodyB] = cache.bodiesOf[index];
            ContactConstraint& c = s.contacts.constraints[k];
            c.contact = index;
            c.indexA = slotOf[bodyA];
            c.indexB = slotOf[bodyB];
            c.pointCount = cache.touchingPoints[index];
            s.contacts.constraintSlots[k] = {c.indexA, c.indexB};
        });
    s.bodies.freeVelocities.resize(s.bodies.states.size());
    w.workers.parallelFor(static_cast<int>(s.bodies.states.size()), 256, [&](int begin, int end, int) {
        for (int slot = begin; slot < end; ++slot) s.bodies.freeVelocities[slot] = velocityWithoutContact(w, ctx, slot);
    });
    propagateImpacts(w, ctx);  // simultaneous impacts, pair by pair, before the substeps
    seedSupportLoads(w, ctx);  // new supports' loads, which the groups read
    findContactGroups(w, ctx);
}

}  // namespace perpdot
