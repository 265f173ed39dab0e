// The contact rows solved eight constraints at a time, for CPUs with AVX2. This file alone is
// compiled with -mavx2 (CMakeLists.txt adds it only where the compiler targets x86-64), and the
// library calls it only after contactLanes8Available() has found AVX2 on the CPU at run time.
// The rows are contact_solver_wide.hpp's, on simd::Float8 lanes; the caller passes raw arrays, so
// no function the rest of the library shares is compiled here.
//
// simd_avx2.hpp comes before contact_solver_wide.hpp: the rows' qualified simd::min and
// simd::clamp are looked up where the template is defined, and must see Float8's overloads.
#include "core/simd.hpp"
#include "core/simd_avx2.hpp"
// (the order above matters, see the comment)
#include "core/contact_solver_wide.hpp"

namespace perpdot {

using simd::Float8;

namespace {

// A body's (v.x, v.y, ω, Δp.x) and (Δp.x, Δp.y, Δq.c, Δq.s) rows (body_lanes.hpp), eight at a time.
struct StateRows {
    __m128 head[8], tail[8];
};

BodyLanes<Float8> gatherBodies8(const BodyState* states, const int (&slots)[8]) {
    StateRows r;
    for (int i = 0; i < 8; ++i) {
        const float* s = reinterpret_cast<const float*>(&states[slots[i]]);
        r.head[i] = _mm_loadu_ps(s);
        r.tail[i] = _mm_loadu_ps(s + 3);
    }
    _MM_TRANSPOSE4_PS(r.head[0], r.head[1], r.head[2], r.head[3]);
    _MM_TRANSPOSE4_PS(r.head[4], r.head[5], r.head[6], r.head[7]);
    _MM_TRANSPOSE4_PS(r.tail[0], r.tail[1], r.tail[2], r.tail[3]);
    _MM_TRANSPOSE4_PS(r.tail[4], r.tail[5], r.tail[6], r.tail[7]);
    auto lane = [](const __m128 (&rows)[8], int field) { return Float8::join(rows[field], rows[field + 4]); };
    return {{lane(r.head, 0), lane(r.head, 1)}, lane(r.head, 2), {lane(r.tail, 0), lane(r.tail, 1)}, {lane(r.tail, 2), lane(r.tail, 3)}};
}

// The velocities back (slot 0, the shared static body, never moves).
void scatterVelocities8(BodyState* states, const int (&slots)[8], const BodyLanes<Float8>& lanes) {
    float vx[8], vy[8], w[8];
    lanes.v.x.store(vx);
    lanes.v.y.store(vy);
    lanes.w.store(w);
    for (int i = 0; i < 8; ++i) {
        if (slots[i] == 0) continue;
        float* s = reinterpret_cast<float*>(&states[slots[i]]);
        s[0] = vx[i];
        s[1] = vy[i];
        s[2] = w[i];
    }
}

}  // namespace

void deriveContactRows8(ContactBlock8& block, const BodyState* freeVelocities, const float (&present)[2][8], const StepContext& ctx) {
    const BodyLanes<Float8> a = gatherBodies8(freeVelocities, block.bodyA);
    const BodyLanes<Float8> b = gatherBodies8(freeVelocities, block.bodyB);
    const Float8 points[2] = {Float8(_mm256_loadu_ps(present[0])), Float8(_mm256_loadu_ps(present[1]))};
    deriveContactRows(*reinterpret_cast<ContactRows<Float8>*>(block.rows), a, b, points, ctx);
}

namespace {

// `rows(blockRows, a, b, block)` on the blocks of [begin, end) that `needs` (all by default).
template <class Rows, class Needs = bool (*)(const ContactBlock8&)>
void forBlocks(ContactBlock8* blocks, int begin, int end, BodyState* states, Rows rows,
               Needs needs = [](const ContactBlock8&) { return true; }) {
    for (int k = begin; k < end; ++k) {
        ContactBlock8& block = blocks[k];
        if (!needs(block)) continue;
        BodyLanes<Float8> a = gatherBodies8(states, block.bodyA);
        BodyLanes<Float8> b = gatherBodies8(states, block.bodyB);
        rows(*reinterpret_cast<ContactRows<Float8>*>(block.rows), a, b, block);
        scatterVelocities8(states, block.bodyA, a);
        scatterVelocities8(states, block.bodyB, b);
    }
}

// The velocity change per substep from its forces of eight slots' bodies, as lanes.
Vec2T<Float8> substepVelocityChange8(const SubstepForces* forces, const int (&slots)[8]) {
    alignas(32) float x[8], y[8];
    for (int lane = 0; lane < 8; ++lane) {
        x[lane] = forces[slots[lane]].dv.x;
        y[lane] = forces[slots[lane]].dv.y;
    }
    return {Float8(_mm256_load_ps(x)), Float8(_mm256_load_ps(y))};
}

}  // namespace

void contactRows8(ContactBlock8* blocks, int begin, int end, BodyState* states, const SubstepForces* forces, const StepContext& ctx,
                  RowPass pass) {
    using Lanes = BodyLanes<Float8>;
    using Rows = ContactRows<Float8>;
    if (pass == RowPass::WarmStart)
        forBlocks(blocks, begin, end, states, [](Rows& c, Lanes& a, Lanes& b, const ContactBlock8&) { warmStartContact(c, a, b); });
    else if (pass == RowPass::Solve)
        forBlocks(blocks, begin, end, states, [&](Rows& c, Lanes& a, Lanes& b, const ContactBlock8&) { solveContact<true>(c, a, b, ctx); });
    else if (pass == RowPass::Relax)
        forBlocks(blocks, begin, end, states, [&](Rows& c, Lanes& a, Lanes& b, const ContactBlock8&) { solveContact<false>(c, a, b, ctx); });
    else
        forBlocks(
            blocks, begin, end, states,
            [&](Rows& c, Lanes& a, Lanes& b, const ContactBlock8& block) {
                restituteContact(c, a, b, substepVelocityChange8(forces, block.bodyA), substepVelocityChange8(forces, block.bodyB), ctx);
            },
            [](const ContactBlock8& block) { return anyElastic(block.rows, ContactBlock8::lanes); });
}

}  // namespace perpdot
