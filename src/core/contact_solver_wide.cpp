// The contact rows solved four at a time. Constraints are graph-coloured (graph_color.hpp) so that
// the four lanes of a block never share a dynamic body; each block gathers its bodies' state
// into lanes, runs the rows of contact_solver_wide.hpp once for all four, and scatters the
// velocities back. Constraints no colour could take (a body touching more than 16 others) are
// solved one by one with the same rows at F = float, after the blocks.
#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>

#include "core/world_impl.hpp"

namespace perpdot {

using simd::Float4;

// ContactRows<float> is nothing but floats, and ContactRows<Float4> is the same fields as Float4s
// in the same order: packing four constraints is a 4×4 transpose of every run of four floats.
constexpr std::size_t rowFloats = sizeof(ContactRows<float>) / sizeof(float);
static_assert(std::is_standard_layout_v<ContactRows<float>> && std::is_standard_layout_v<ContactRows<Float4>>);
static_assert(sizeof(ContactRows<float>) == rowFloats * sizeof(float) &&
              sizeof(ContactRows<Float4>) == rowFloats * sizeof(Float4) && rowFloats >= 4);

void packContactRows(const std::array<const ContactRows<float>*, 4>& lanes, ContactRows<Float4>& packed) {
    auto* out = reinterpret_cast<Float4*>(&packed);
    for (std::size_t k = 0; k < rowFloats; k += 4) {
        const std::size_t first = std::min(k, rowFloats - 4);  // the last run overlaps the one before
        Float4 run[4];
        for (int i = 0; i < 4; ++i) run[i] = Float4::loadBytes(reinterpret_cast<const float*>(lanes[i]) + first);
        simd::transpose(run);
        std::copy(run, run + 4, out + first);
    }
}

namespace {

// `rows(blockRows, a, b)` on blocks [begin, end), or `rows(constraint, a, b)` on every overflow
// constraint when overflow is set.
template <class Rows>
void forContacts(World::Impl& w, int begin, int end, bool overflow, Rows rows) {
    std::vector<BodyState>& states = w.states;
    for (int k = begin; k < end; ++k) {
        ContactBlock& block = w.contactBlocks[k];
        BodyLanes<Float4> a = gatherBodies(states, block.bodyA);
        BodyLanes<Float4> b = gatherBodies(states, block.bodyB);
        rows(block.rows, a, b);
        scatterVelocities(states, block.bodyA, a);
        scatterVelocities(states, block.bodyB, b);
    }
    if (!overflow) return;
    for (int index : w.overflowConstraints) {
        ContactConstraint& c = w.constraints[index];
        rows(c, states[c.indexA], states[c.indexB]);
    }
}

void passContacts(World::Impl& w, const StepContext& ctx, RowPass pass, int begin, int end, bool overflow) {
    if (pass == RowPass::WarmStart)
        forContacts(w, begin, end, overflow, [](auto& c, auto& a, auto& b) { warmStartContact(c, a, b); });
    else
        forContacts(w, begin, end, overflow,
                    [&, useBias = pass == RowPass::Solve](auto& c, auto& a, auto& b) { solveContact(c, a, b, ctx, useBias); });
}

}  // namespace

// Colour the constraints in order, then lay them out colour by colour (Box2D v3's solve order:
// it keeps stacks as stiff as the plain constraint order does), four to a block; overflow last.
// The constraints of contact groups solved directly (contact_groups.hpp) take no colour.
void prepareContactBlocks(World::Impl& w) {
    constexpr int overflow = GraphColoring::overflow;
    const int count = static_cast<int>(w.constraints.size());
    w.contactColoring.reset(static_cast<int>(w.states.size()));
    w.contactColors.resize(w.constraints.size());
    const std::vector<uint8_t>& direct = w.contactGroups.direct;  // solved by their groups instead
    for (int index = 0; index < count; ++index) {
        const auto [slotA, slotB] = w.constraintSlots[index];
        w.contactColors[index] = direct[index] ? overflow : w.contactColoring.assign(slotA, slotB);
    }
    const ColorStarts start = sortByColor(w.contactColors, w.contactOrder);

    // Blocks of four constraints of one colour; the last block of a colour may have empty lanes.
    w.contactBlockStart[0] = 0;
    for (int color = 0; color <= overflow; ++color)
        w.contactBlockStart[color + 1] =
            w.contactBlockStart[color] + (color < overflow ? (start[color + 1] - start[color] + 3) / 4 : 0);
    const int blocks = w.contactBlockStart[overflow];
    w.contactBlocks.resize(static_cast<size_t>(blocks));  // reused memory: every field is rewritten
    static const ContactRows<float> emptyLane;  // no mass, no impulse: leaves the bodies alone
    // Block b of colour c holds the constraints contactOrder[start[c] + 4 (b − blockStart[c]) ...].
    w.workers.parallelFor(blocks, 32, [&](int begin, int stop, int) {
        int color = static_cast<int>(std::upper_bound(w.contactBlockStart.begin(), w.contactBlockStart.end(), begin) -
                                     w.contactBlockStart.begin()) - 1;
        for (int b = begin; b < stop; ++b) {
            while (b >= w.contactBlockStart[color + 1]) ++color;
            ContactBlock& block = w.contactBlocks[b];
            std::array<const ContactRows<float>*, 4> lanes;
            for (int lane = 0; lane < 4; ++lane) {
                const int position = start[color] + 4 * (b - w.contactBlockStart[color]) + lane;
                const int index = position < start[color + 1] ? w.contactOrder[position] : -1;
                const ContactConstraint* c = index < 0 ? nullptr : &w.constraints[index];
                block.constraint[lane] = index;
                block.bodyA[lane] = c ? c->indexA : 0;
                block.bodyB[lane] = c ? c->indexB : 0;
                lanes[lane] = c ? c : &emptyLane;
            }
            packContactRows(lanes, block.rows);
        }
    });
    w.overflowConstraints.clear();
    for (int position = start[overflow]; position < count; ++position)
        if (!direct[w.contactOrder[position]]) w.overflowConstraints.push_back(w.contactOrder[position]);
}

int contactBlockCount(const World::Impl& w, int color) {
    return w.contactBlockStart[color + 1] - w.contactBlockStart[color];
}

void contactRows(World::Impl& w, const StepContext& ctx, RowPass pass, int color, int begin, int end) {
    const int first = w.contactBlockStart[color];
    passContacts(w, ctx, pass, first + begin, first + end, false);
}

void serialContactRows(World::Impl& w, const StepContext& ctx, RowPass pass) { passContacts(w, ctx, pass, 0, 0, true); }

namespace {

// A block's accumulated impulses back into its four constraints.
void unpackContactBlock(World::Impl& w, const ContactBlock& block) {
    float rolling[4], normal[2][4], tangent[2][4], maxNormal[2][4];
    block.rows.rollingImpulse.store(rolling);
    for (int i = 0; i < 2; ++i) {
        block.rows.points[i].normalImpulse.store(normal[i]);
        block.rows.points[i].tangentImpulse.store(tangent[i]);
        block.rows.points[i].maxNormalImpulse.store(maxNormal[i]);
    }
    for (int lane = 0; lane < 4; ++lane) {
        if (block.constraint[lane] < 0) continue;
        ContactConstraint& c = w.constraints[block.constraint[lane]];
        c.rollingImpulse = rolling[lane];
        for (int i = 0; i < c.pointCount; ++i) {
            c.points[i].normalImpulse = normal[i][lane];
            c.points[i].tangentImpulse = tangent[i][lane];
            c.points[i].maxNormalImpulse = maxNormal[i][lane];
        }
    }
}

}  // namespace

void unpackContactBlocks(World::Impl& w) {
    w.workers.parallelFor(static_cast<int>(w.contactBlocks.size()), 64, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) unpackContactBlock(w, w.contactBlocks[k]);
    });
}

}  // namespace perpdot
