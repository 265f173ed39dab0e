// The contact rows solved four (SSE2) or eight (AVX2, contact_solver_avx2.cpp) at a time.
// Constraints are graph-coloured (graph_color.hpp) so that the lanes of a block never share a
// dynamic body; each block gathers its bodies' state into lanes, runs the rows of
// contact_solver_wide.hpp once for all of them, and scatters the velocities back. Constraints no
// colour could take (a body touching more than 16 others) are solved one by one with the same rows
// at F = float, after the blocks.
#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <type_traits>

#include "core/solver/contact_prepare.hpp"
#include "core/solver/contact_solver.hpp"
#include "core/solver/support_sinks.hpp"

namespace perpdot {

using simd::Float4;

bool contactLanes8Available() {
#ifdef PERPDOT_AVX2
    return __builtin_cpu_supports("avx2");
#else
    return false;
#endif
}

// Eight lanes where the CPU has AVX2, unless PERPDOT_CONTACT_LANES=4 asks for four (to compare
// the two: the results are the same bits).
int chooseContactLanes() {
    const char* asked = std::getenv("PERPDOT_CONTACT_LANES");
    if (asked != nullptr && std::strcmp(asked, "4") == 0) return 4;
    return contactLanes8Available() ? 8 : 4;
}

namespace {

// fn(blocks) on the step's contact blocks: of eight lanes (contactLanes = 8) or of four.
template <class Scratch, class Fn>
decltype(auto) onContactBlocks(Scratch& contacts, Fn fn) {
#ifdef PERPDOT_AVX2
    if (contacts.lanes == 8) return fn(contacts.blocks8);
#endif
    return fn(contacts.blocks);
}

// deriveContactBlock on a block's lanes: four here, eight in the AVX2 file.
void deriveBlock(const SolverWorld& w, const StepContext& ctx, ContactBlock<4>& block, const float (&present)[2][4]) {
    deriveContactBlock<Float4>(block, w.scratch.bodies.freeVelocities.data(), present, ctx);
}

#ifdef PERPDOT_AVX2
void deriveBlock(const SolverWorld& w, const StepContext& ctx, ContactBlock<8>& block, const float (&present)[2][8]) {
    deriveContactRows8(block, w.scratch.bodies.freeVelocities.data(), present, ctx);
}
#endif

// A support row (support_sinks.hpp), laid out at `at`: its contact's rest sink settled from the
// points' λ₀ and effective masses, and its points solved that much deeper (baseSeparation less it).
template <std::size_t lanes>
void offsetSupportRow(const SolverWorld& w, RowLane<lanes> at, int k, const RestSinkTerms& terms) {
    using R = ContactRows<float>;
    using P = ContactPointRows<float>;
    const ContactConstraint& c = w.scratch.contacts.constraints[static_cast<size_t>(k)];
    const float invMassA = w.scratch.bodies.freeVelocities[c.indexA].invMass, invMassB = w.scratch.bodies.freeVelocities[c.indexB].invMass;
    if (supportedSide(at.vec(offsetof(R, normal)), terms.up, invMassA, invMassB) == 0) return;
    constexpr std::size_t second = sizeof(P);
    float impulseK = at[offsetof(R, points) + offsetof(P, normalImpulse)] / at[offsetof(R, points) + offsetof(P, normalMass)];
    if (c.pointCount > 1) impulseK += at[offsetof(R, points) + second + offsetof(P, normalImpulse)] / at[offsetof(R, points) + second + offsetof(P, normalMass)];
    Contact& contact = w.contactCache.contacts[c.contact];
    const bool fixed = invMassA == 0.0f || invMassB == 0.0f;
    contact.restSink = settledRestSink(contact.restSink, impulseK, c.pointCount, fixed, w.scratch.contacts.support.seeded[static_cast<size_t>(k)] != 0, terms);
    at[offsetof(R, points) + offsetof(P, baseSeparation)] -= contact.restSink;
    if (c.pointCount > 1) at[offsetof(R, points) + second + offsetof(P, baseSeparation)] -= contact.restSink;
}

// Blocks of Block::lanes constraints of one colour, in colour order (the last block of a colour
// may have empty lanes): block b of colour c holds the constraints contactOrder[start[c] + lanes
// (b − blockStart[c]) ...]. Sized here, laid out by the solver's first stages (layOutBlocks).
template <class Block>
void sizeBlocks(ContactScratch& contacts, std::vector<Block>& blocks) {
    constexpr int overflow = GraphColoring::overflow;
    constexpr int width = Block::lanes;
    const ColorStarts& start = contacts.colorStart;
    ColorStarts& blockStart = contacts.blockStart;
    blockStart[0] = 0;
    for (int color = 0; color <= overflow; ++color)
        blockStart[color + 1] = blockStart[color] + (color < overflow ? (start[color + 1] - start[color] + width - 1) / width : 0);
    blocks.resize(static_cast<size_t>(blockStart[overflow]));  // reused memory: every field is rewritten
}

// Blocks [begin, end) of colour `color`: the lanes' contact values gathered into them four or eight
// at a time (gatherContactLanes), then the block's rows derived lanes at once (contact_prepare.hpp).
template <class Block>
void layOutBlocks(const SolverWorld& w, const StepContext& ctx, std::vector<Block>& blocks, int color, int begin, int end) {
    constexpr int width = Block::lanes;
    const SolverWorld::Scratch& s = w.scratch;
    const int colorStart = s.contacts.colorStart[color], colorEnd = s.contacts.colorStart[color + 1];
    const RestSinkTerms terms = restSinkTerms(w.gravity, ctx);
    for (int b = begin; b < end; ++b) {
        Block& block = blocks[s.contacts.blockStart[color] + b];
        const int position = colorStart + width * b;  // of the lanes' constraints in contactOrder
        const int lanes = std::min(width, colorEnd - position);
        alignas(32) float present[2][width];  // 1 where a lane's point is a manifold point
        const ContactConstraint* constraints[width];
        const int* order = &s.contacts.order[position];
        // The lanes' contacts lie anywhere in the pool: the next block's (the constraints right
        // after these in contactOrder) load while this block gathers, and this block's own were
        // asked for by the block before (the first of a range asks for them here).
        const int fetchEnd = std::min(position + lanes + width, colorEnd);
        for (int p = b == begin ? position : position + lanes; p < fetchEnd; ++p)
            prefetchSolverFields<0>(w.contactCache.contacts[s.contacts.constraints[s.contacts.order[p]].contact]);
        for (int lane = 0; lane < width; ++lane) {
            const bool used = lane < lanes;
            const ContactConstraint* c = used ? &s.contacts.constraints[order[lane]] : nullptr;
            block.item[lane] = used ? c->contact : -1;
            block.bodyA[lane] = used ? c->indexA : 0;  // an empty lane: the static slot
            block.bodyB[lane] = used ? c->indexB : 0;
            for (int i = 0; i < 2; ++i) present[i][lane] = used && i < c->pointCount ? 1.0f : 0.0f;
            constraints[lane] = c;
        }
        gatherContactLanes(w, constraints, lanes, block, present);
        deriveBlock(w, ctx, block, present);
        if (terms.any)
            for (int lane = 0; lane < lanes; ++lane) offsetSupportRow(w, RowLane<width>{block.rows.data + lane}, order[lane], terms);
        block.head = rowUses(block.rows.data, width, lanes);
        // An empty lane (the last block of a colour may have some): no mass, no impulse, nothing at
        // all. Field by field: GCC 12 at -O3 turned the lane-by-lane order into aligned 16-byte
        // stores from an unaligned lane (a crash at three lanes of eight).
        if (lanes < width)
            for (std::size_t field = 0; field < rowFloats; ++field)
                for (int lane = lanes; lane < width; ++lane) block.rows.data[field * width + static_cast<std::size_t>(lane)] = 0.0f;
    }
}

}  // namespace

// Colour the constraints in order, in the colouring the joints began (colorJoints: one graph, so
// a colour's joints and contacts share no moving body either), then size their blocks colour by
// colour (Box2D v3's solve order: it keeps stacks as stiff as the plain constraint order does),
// four or eight to a block, laid out by the solver's first stages; overflow last, prepared here
// into their own rows. The lane width changes no result:
// a colour's constraints share no moving body. The constraints of contact groups solved directly
// (contact_groups.hpp) take no colour: their groups prepared them.
void prepareContactBlocks(const SolverWorld& w, const StepContext& ctx) {
    const SolverWorld::Scratch& s = w.scratch;
    constexpr int overflow = GraphColoring::overflow;
    const int count = static_cast<int>(s.contacts.constraints.size());
    s.contacts.colors.resize(s.contacts.constraints.size());
    const std::vector<uint8_t>& direct = s.contacts.groups.direct;  // solved by their groups instead
    const int slots = static_cast<int>(s.bodies.states.size());
    for (int index = 0; index < count; ++index) {
        const auto [slotA, slotB] = s.contacts.constraintSlots[index];
        const int color = direct[index] ? overflow : s.coloring.assign(slotA, slotB);
        // The overflow's constraints are solved one after another: in constraint order.
        s.contacts.colors[index] = color * slotBuckets + (color == overflow ? 0 : slotBucket(slotA, slotB, slots));
    }
    const ColorStarts& start = s.contacts.colorStart = sortByColor(s.contacts.colors, s.contacts.order);
    onContactBlocks(s.contacts, [&](auto& blocks) { sizeBlocks(s.contacts, blocks); });
    s.contacts.overflow.clear();
    const RestSinkTerms terms = restSinkTerms(w.gravity, ctx);
    for (int position = start[overflow]; position < count; ++position) {
        const int index = s.contacts.order[position];
        if (direct[index]) continue;
        s.contacts.overflow.push_back(index);
        prepareContactRows(w, ctx, s.contacts.constraints[index], s.contacts.constraintRows[index]);
        if (terms.any) offsetSupportRow(w, RowLane<1>{floatsOf(s.contacts.constraintRows[index])}, index, terms);
    }
}

// Where each constraint's rows are: lane slot % lanes of block slot / lanes, or -1 for its own
// rows. Layout leaves this implicit in the colour order: writing it into the constraints there,
// scattered, had the workers share the constraints' cache lines.
void locateContactRows(ContactScratch& c) {
    c.rowSlot.assign(c.constraints.size(), -1);
    for (int color = 0; color < GraphColoring::overflow; ++color)
        for (int p = c.colorStart[color]; p < c.colorStart[color + 1]; ++p)
            c.rowSlot[c.order[p]] = c.blockStart[color] * c.lanes + (p - c.colorStart[color]);
}

// Field `field` (a float index, pointField) of constraint k's rows, in its lane or its own rows.
float contactRowField(const ContactScratch& contacts, int k, std::size_t field) {
    const int slot = contacts.rowSlot[k];
    if (slot < 0) return floatsOf(contacts.constraintRows[k])[field];
    return onContactBlocks(contacts, [&](const auto& blocks) {
        constexpr std::size_t lanes = std::remove_cvref_t<decltype(blocks[0])>::lanes;
        const auto place = static_cast<std::size_t>(slot);
        return blocks[place / lanes].rows.data[field * lanes + place % lanes];
    });
}

void layOutContactBlocks(const SolverWorld& w, const StepContext& ctx, int color, int begin, int end) {
    onContactBlocks(w.scratch.contacts, [&](auto& blocks) { layOutBlocks(w, ctx, blocks, color, begin, end); });
}

int contactBlockCount(const ContactScratch& contacts, int color) {
    return contacts.blockStart[color + 1] - contacts.blockStart[color];
}

void contactRows(ContactScratch& contacts, SolverBodies& bodies, const StepContext& ctx, RowPass pass, int color, int begin, int end) {
    const int first = contacts.blockStart[color];
#ifdef PERPDOT_AVX2
    if (contacts.lanes == 8)
        return contactRows8(contacts.blocks8.data(), first + begin, first + end, bodies.states.data(), bodies.substepForces.data(), ctx, pass);
#endif
    contactBlockRows<Float4>(contacts.blocks.data(), first + begin, first + end, bodies.states.data(), bodies.substepForces.data(), ctx, pass);
}

// The overflow constraints one by one, in their own rows.
void serialContactRows(ContactScratch& contacts, SolverBodies& bodies, const StepContext& ctx, RowPass pass) {
    forPass<float>(pass, ctx, bodies.substepForces.data(), [&](auto rows, auto) {
        for (int index : contacts.overflow) {
            const ContactConstraint& c = contacts.constraints[index];
            rows(contacts.constraintRows[index], bodies.states[c.indexA], bodies.states[c.indexB], c.indexA, c.indexB, RowUses{});
        }
    });
}

namespace {

// Stored field f of a constraint's rows (a line of storedRowFields), from its lane `rows`, into
// its contact: a contact's field where point < 0, a point field into point `point`.
template <ContactRowField f, std::size_t lanes>
void storeRowField(RowLane<lanes, const float> rows, Contact& contact, int point) {
    if constexpr (f.pointStride == 0) {
        if (point < 0) *reinterpret_cast<float*>(reinterpret_cast<char*>(&contact) + f.contact) = rows[f.row];
    } else if (point >= 0) {
        *reinterpret_cast<float*>(reinterpret_cast<char*>(&contact.points[point]) + f.contact) =
            rows[f.row + static_cast<std::size_t>(point) * f.pointStride];
    }
}

// The stored fields of a constraint's rows (storedRowFields: the accumulated impulses and each
// point's largest push), from its lane `rows`, into its contact.
template <std::size_t lanes>
void storeContactRows(RowLane<lanes, const float> rows, Contact& contact) {
    forEachRowField<storedRowFields>([&](auto field) { storeRowField<decltype(field)::value>(rows, contact, -1); });
    for (int i = 0; i < 2; ++i)
        if (i < contact.pointCount) forEachRowField<storedRowFields>([&](auto field) { storeRowField<decltype(field)::value>(rows, contact, i); });
}

// A block's accumulated impulses straight from its lanes into its contacts.
template <class Block>
void storeBlockImpulses(ContactCache& cache, const Block& block) {
    for (int lane = 0; lane < Block::lanes; ++lane)
        if (block.item[lane] >= 0)
            storeContactRows(RowLane<Block::lanes, const float>{block.rows.data + lane}, cache.contacts[block.item[lane]]);
}

template <class Block>
void storeBlocks(ContactCache& cache, const std::vector<Block>& blocks, int begin, int end) {
    for (int k = begin; k < end; ++k) {
        if (k + 1 < end)  // the next block's contacts load while this one's are written
            for (int contact : blocks[k + 1].item)
                if (contact >= 0) prefetchSolverFields<1>(cache.contacts[contact]);
        storeBlockImpulses(cache, blocks[k]);
    }
}

}  // namespace

// The impulses for the next step's warm start (a contact has one constraint: the workers write
// apart). A colour's blocks from their lanes, as the solver's last stages (SolverStages) ...
void storeContactBlocks(const ContactScratch& contacts, ContactCache& cache, int color, int begin, int end) {
    const int first = contacts.blockStart[color];
    onContactBlocks(contacts, [&](const auto& blocks) { storeBlocks(cache, blocks, first + begin, first + end); });
}

// ... then those of the overflow constraints and of the contact groups solved directly, from their rows.
void storeContactImpulses(const ContactScratch& contacts, ContactCache& cache) {
    auto storeRows = [&](int index) {
        storeContactRows(RowLane<1, const float>{floatsOf(contacts.constraintRows[index])}, cache.contacts[contacts.constraints[index].contact]);
    };
    for (int index : contacts.overflow) storeRows(index);
    for (int index : contacts.groups.constraints) storeRows(index);
}

}  // namespace perpdot
