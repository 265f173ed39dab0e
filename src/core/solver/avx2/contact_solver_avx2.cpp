// The contact rows solved eight constraints at a time, for CPUs with AVX2. This file alone is
// compiled with -mavx2 (CMakeLists.txt adds it only where the compiler targets x86-64), and the
// library calls it only after contactLanes8Available() has found AVX2 on the CPU at run time.
// The rows are contact_solver_wide.hpp's, on simd::Float8 lanes; the caller passes raw arrays, so
// no function the rest of the library shares is compiled here.
//
// simd_avx2.hpp comes before contact_solver_wide.hpp: the rows' qualified simd::min and
// simd::clamp are looked up where the template is defined, and must see Float8's overloads.
#include "simd/simd.hpp"
#include "simd/simd_avx2.hpp"
// (the order above matters, see the comment)
#include "core/solver/contact_solver_wide.hpp"

namespace perpdot {

using simd::Float8;

namespace {

// Eight rows of eight floats turned into eight lanes, field f of row i into lane i of field(f): the
// 8x8 transpose, unpack pairs of rows, shuffle quads, swap halves.
struct Transposed8 {
    __m256 quads[8];
    // Field f < 4 is the low halves of quads[f] (rows 0-3) and quads[f + 4] (rows 4-7); f ≥ 4 the high ones.
    [[gnu::always_inline]] Float8 field(int f) const {
        return Float8(f < 4 ? _mm256_permute2f128_ps(quads[f], quads[f + 4], 0x20) : _mm256_permute2f128_ps(quads[f - 4], quads[f], 0x31));
    }
};

[[gnu::always_inline]] inline Transposed8 transpose8(const __m256 (&row)[8]) {
    __m256 pairs[8];
    Transposed8 t;
    for (int i = 0; i < 8; i += 2) {
        pairs[i] = _mm256_unpacklo_ps(row[i], row[i + 1]);
        pairs[i + 1] = _mm256_unpackhi_ps(row[i], row[i + 1]);
    }
    for (int i = 0; i < 8; i += 4) {
        t.quads[i] = _mm256_shuffle_ps(pairs[i], pairs[i + 2], 0x44);
        t.quads[i + 1] = _mm256_shuffle_ps(pairs[i], pairs[i + 2], 0xEE);
        t.quads[i + 2] = _mm256_shuffle_ps(pairs[i + 1], pairs[i + 3], 0x44);
        t.quads[i + 3] = _mm256_shuffle_ps(pairs[i + 1], pairs[i + 3], 0xEE);
    }
    return t;
}

}  // namespace

template <>
struct ContactRuns<Float8> {
    static void transpose(const float* const (&runs)[8], Float8 (&fields)[7]) {
        __m256 row[8];
        for (int k = 0; k < 8; ++k) row[k] = _mm256_loadu_ps(runs[k]);
        const Transposed8 t = transpose8(row);
        for (int f = 0; f < 7; ++f) fields[f] = t.field(f);
    }
};

template <>
struct LaneBodies<Float8> {
    using Slots = int[8];

    // Each body's state (v.x, v.y, ω, Δp.x, Δp.y, Δq.c, Δq.s, 1/m: body_lanes.hpp) as an aligned
    // row of eight floats, turned into lanes.
    [[gnu::always_inline]] static BodyLanes<Float8> gather(const BodyState* states, const Slots& slots) {
        static_assert(sizeof(BodyState) == 8 * sizeof(float) && alignof(BodyState) == 32);
        __m256 row[8];
        for (int i = 0; i < 8; ++i) row[i] = _mm256_load_ps(reinterpret_cast<const float*>(&states[slots[i]]));
        const Transposed8 t = transpose8(row);
        auto field = [&](int f) { return t.field(f); };
        return {{field(0), field(1)}, field(2), {field(3), field(4)}, {field(5), field(6)}, field(7)};
    }

    // The velocities back: the inverse transpose of (v.x, v.y, ω, Δp.x) into each body's first four
    // floats, Δp.x as gathered (the rows leave it alone). Slot 0, the shared static body, never moves.
    [[gnu::always_inline]] static void scatter(BodyState* states, const Slots& slots, const BodyLanes<Float8>& lanes) {
        const __m256 vxvy01 = _mm256_unpacklo_ps(lanes.v.x.v, lanes.v.y.v), vxvy23 = _mm256_unpackhi_ps(lanes.v.x.v, lanes.v.y.v);
        const __m256 wdp01 = _mm256_unpacklo_ps(lanes.w.v, lanes.dp.x.v), wdp23 = _mm256_unpackhi_ps(lanes.w.v, lanes.dp.x.v);
        // Row i (i < 4) of bodies i and i + 4, in the low and high halves.
        const __m256 rows[4] = {_mm256_shuffle_ps(vxvy01, wdp01, 0x44), _mm256_shuffle_ps(vxvy01, wdp01, 0xEE),
                                _mm256_shuffle_ps(vxvy23, wdp23, 0x44), _mm256_shuffle_ps(vxvy23, wdp23, 0xEE)};
        for (int i = 0; i < 4; ++i) {
            if (slots[i] != 0) _mm_storeu_ps(reinterpret_cast<float*>(&states[slots[i]]), _mm256_castps256_ps128(rows[i]));
            if (slots[i + 4] != 0) _mm_storeu_ps(reinterpret_cast<float*>(&states[slots[i + 4]]), _mm256_extractf128_ps(rows[i], 1));
        }
    }

    // The velocity change per substep from its forces of eight slots' bodies, as lanes.
    static Vec2T<Float8> velocityChange(const SubstepForces* forces, const Slots& slots) {
        alignas(32) float x[8], y[8];
        for (int lane = 0; lane < 8; ++lane) {
            x[lane] = forces[slots[lane]].dv.x;
            y[lane] = forces[slots[lane]].dv.y;
        }
        return {Float8(_mm256_load_ps(x)), Float8(_mm256_load_ps(y))};
    }
};

void gatherContactRows8(ContactBlock<8>& block, const float* const (&head)[8], const float* const (&points)[2][8], const float (&present)[2][8]) {
    gatherContactRuns<Float8>(block, head, points, present);
}

void deriveContactRows8(ContactBlock<8>& block, const BodyState* freeVelocities, const float (&present)[2][8], const StepContext& ctx) {
    deriveContactBlock<Float8>(block, freeVelocities, present, ctx);
}

void contactRows8(ContactBlock<8>* blocks, int begin, int end, BodyState* states, const SubstepForces* forces, const StepContext& ctx,
                  RowPass pass) {
    contactBlockRows<Float8>(blocks, begin, end, states, forces, ctx, pass);
}

}  // namespace perpdot
