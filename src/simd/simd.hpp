// Float4: four float lanes for the wide contact and joint solvers. SSE2 on x86-64, NEON on ARM64;
// elsewhere, or when PERPDOT_NO_SIMD is defined, a plain struct of four floats with the same semantics.
//
// Only exactly rounded IEEE operations are offered (+, −, ×, ÷, √, negation, min, max, compare and
// select: what the contact and joint rows use): no FMA and no approximate reciprocal, so every lane computes
// bit for bit what the scalar `float` code computes. The float overloads of min, max and select below give the scalar
// (1-lane) case the very same semantics, so one template serves both.
#pragma once

#include <cmath>

#if !defined(PERPDOT_NO_SIMD) && (defined(__SSE2__) || defined(_M_X64))
#define PERPDOT_SSE2 1
#include <emmintrin.h>
#elif !defined(PERPDOT_NO_SIMD) && defined(__aarch64__) && defined(__ARM_NEON)
#define PERPDOT_NEON 1
#include <arm_neon.h>
#else
#include <cstring>
#include <utility>
#endif

namespace perpdot::simd {

// The 1-lane case. max(a, b) = a > b ? a : b and min(a, b) = a < b ? a : b, as SSE's maxps/minps
// define them (the second operand when the comparison is false, e.g. for ±0 or NaN).
inline float min(float a, float b) { return a < b ? a : b; }
inline float max(float a, float b) { return a > b ? a : b; }
inline float select(bool mask, float ifTrue, float ifFalse) { return mask ? ifTrue : ifFalse; }
inline float sqrt(float a) { return std::sqrt(a); }

#ifdef PERPDOT_SSE2

struct Mask4 {
    __m128 m;
};

struct Float4 {
    __m128 v;

    Float4() : v(_mm_setzero_ps()) {}
    Float4(float s) : v(_mm_set1_ps(s)) {}  // implicit: a float broadcasts, so it mixes with lanes like a scalar
    explicit Float4(__m128 m) : v(m) {}
    static Float4 load(const float* p) { return Float4(_mm_loadu_ps(p)); }
    // Four consecutive floats of a struct's storage, e.g. of a body's state.
    static Float4 loadBytes(const void* p) { return Float4(_mm_loadu_ps(static_cast<const float*>(p))); }
    void store(float* p) const { _mm_storeu_ps(p, v); }

    friend Float4 operator+(Float4 a, Float4 b) { return Float4(_mm_add_ps(a.v, b.v)); }
    friend Float4 operator-(Float4 a, Float4 b) { return Float4(_mm_sub_ps(a.v, b.v)); }
    friend Float4 operator*(Float4 a, Float4 b) { return Float4(_mm_mul_ps(a.v, b.v)); }
    friend Float4 operator/(Float4 a, Float4 b) { return Float4(_mm_div_ps(a.v, b.v)); }
    friend Float4 operator-(Float4 a) { return Float4(_mm_xor_ps(a.v, _mm_set1_ps(-0.0f))); }  // flips the sign bit, as -x does
    Float4& operator+=(Float4 b) { return *this = *this + b; }

    friend Mask4 operator>(Float4 a, Float4 b) { return {_mm_cmpgt_ps(a.v, b.v)}; }
    friend Mask4 operator!=(Float4 a, Float4 b) { return {_mm_cmpneq_ps(a.v, b.v)}; }
};

inline Float4 min(Float4 a, Float4 b) { return Float4(_mm_min_ps(a.v, b.v)); }
inline Float4 max(Float4 a, Float4 b) { return Float4(_mm_max_ps(a.v, b.v)); }
inline Float4 sqrt(Float4 a) { return Float4(_mm_sqrt_ps(a.v)); }
inline Float4 select(Mask4 mask, Float4 ifTrue, Float4 ifFalse) {
    return Float4(_mm_or_ps(_mm_and_ps(mask.m, ifTrue.v), _mm_andnot_ps(mask.m, ifFalse.v)));
}
inline Mask4 operator|(Mask4 a, Mask4 b) { return {_mm_or_ps(a.m, b.m)}; }
// Bit i set where lane i holds.
inline unsigned laneBits(Mask4 mask) { return static_cast<unsigned>(_mm_movemask_ps(mask.m)); }
// Whether a mask holds in no lane, in every lane.
inline bool noLane(Mask4 mask) { return _mm_movemask_ps(mask.m) == 0; }
inline bool allLanes(Mask4 mask) { return _mm_movemask_ps(mask.m) == 0xF; }

// Rows to columns: afterwards lane i of m[j] is what lane j of m[i] was.
inline void transpose(Float4 (&m)[4]) { _MM_TRANSPOSE4_PS(m[0].v, m[1].v, m[2].v, m[3].v); }

#elif defined(PERPDOT_NEON)  // ARM64: the same operations as SSE2's, lane for lane and bit for bit

struct Mask4 {
    uint32x4_t m;
};

struct Float4 {
    float32x4_t v;

    Float4() : v(vdupq_n_f32(0.0f)) {}
    Float4(float s) : v(vdupq_n_f32(s)) {}  // implicit: a float broadcasts, so it mixes with lanes like a scalar
    explicit Float4(float32x4_t m) : v(m) {}
    static Float4 load(const float* p) { return Float4(vld1q_f32(p)); }
    // Four consecutive floats of a struct's storage, e.g. of a body's state.
    static Float4 loadBytes(const void* p) { return Float4(vld1q_f32(static_cast<const float*>(p))); }
    void store(float* p) const { vst1q_f32(p, v); }

    // Separate multiplies and adds (the build's -ffp-contract=off keeps them from fusing into fmla).
    friend Float4 operator+(Float4 a, Float4 b) { return Float4(vaddq_f32(a.v, b.v)); }
    friend Float4 operator-(Float4 a, Float4 b) { return Float4(vsubq_f32(a.v, b.v)); }
    friend Float4 operator*(Float4 a, Float4 b) { return Float4(vmulq_f32(a.v, b.v)); }
    friend Float4 operator/(Float4 a, Float4 b) { return Float4(vdivq_f32(a.v, b.v)); }
    friend Float4 operator-(Float4 a) { return Float4(vnegq_f32(a.v)); }  // flips the sign bit, as -x does
    Float4& operator+=(Float4 b) { return *this = *this + b; }

    friend Mask4 operator>(Float4 a, Float4 b) { return {vcgtq_f32(a.v, b.v)}; }
    friend Mask4 operator!=(Float4 a, Float4 b) { return {vmvnq_u32(vceqq_f32(a.v, b.v))}; }
};

// min and max by compare and select, as SSE's minps/maxps and the float overloads define them
// (NEON's vminq/vmaxq treat ±0 and NaN otherwise).
inline Float4 min(Float4 a, Float4 b) { return Float4(vbslq_f32(vcltq_f32(a.v, b.v), a.v, b.v)); }
inline Float4 max(Float4 a, Float4 b) { return Float4(vbslq_f32(vcgtq_f32(a.v, b.v), a.v, b.v)); }
inline Float4 sqrt(Float4 a) { return Float4(vsqrtq_f32(a.v)); }
inline Float4 select(Mask4 mask, Float4 ifTrue, Float4 ifFalse) { return Float4(vbslq_f32(mask.m, ifTrue.v, ifFalse.v)); }
inline Mask4 operator|(Mask4 a, Mask4 b) { return {vorrq_u32(a.m, b.m)}; }
// Bit i set where lane i holds.
inline unsigned laneBits(Mask4 mask) {
    const uint32x4_t bit = {1u, 2u, 4u, 8u};
    return vaddvq_u32(vandq_u32(mask.m, bit));
}
// Whether a mask holds in no lane, in every lane.
inline bool noLane(Mask4 mask) { return vmaxvq_u32(mask.m) == 0; }
inline bool allLanes(Mask4 mask) { return vminvq_u32(mask.m) != 0; }

// Rows to columns: afterwards lane i of m[j] is what lane j of m[i] was.
inline void transpose(Float4 (&m)[4]) {
    const float32x4x2_t ab = vtrnq_f32(m[0].v, m[1].v), cd = vtrnq_f32(m[2].v, m[3].v);  // (a0 b0 a2 b2), (a1 b1 a3 b3)
    m[0].v = vcombine_f32(vget_low_f32(ab.val[0]), vget_low_f32(cd.val[0]));
    m[1].v = vcombine_f32(vget_low_f32(ab.val[1]), vget_low_f32(cd.val[1]));
    m[2].v = vcombine_f32(vget_high_f32(ab.val[0]), vget_high_f32(cd.val[0]));
    m[3].v = vcombine_f32(vget_high_f32(ab.val[1]), vget_high_f32(cd.val[1]));
}

#else  // the portable fallback: the same operations lane by lane

struct Mask4 {
    bool m[4] = {};
};

struct Float4 {
    float v[4] = {};

    Float4() = default;
    Float4(float s) : v{s, s, s, s} {}  // implicit: a float broadcasts, so it mixes with lanes like a scalar

    static Float4 load(const float* p) {
        Float4 r;
        for (int i = 0; i < 4; ++i) r.v[i] = p[i];
        return r;
    }
    // Four consecutive floats of a struct's storage, e.g. of a body's state.
    static Float4 loadBytes(const void* p) {
        Float4 r;
        std::memcpy(r.v, p, sizeof r.v);
        return r;
    }
    void store(float* p) const {
        for (int i = 0; i < 4; ++i) p[i] = v[i];
    }

    template <class Op>
    static Float4 lanewise(Float4 a, Float4 b, Op op) {
        Float4 r;
        for (int i = 0; i < 4; ++i) r.v[i] = op(a.v[i], b.v[i]);
        return r;
    }
    template <class Op>
    static Mask4 compare(Float4 a, Float4 b, Op op) {
        Mask4 r;
        for (int i = 0; i < 4; ++i) r.m[i] = op(a.v[i], b.v[i]);
        return r;
    }

    friend Float4 operator+(Float4 a, Float4 b) { return lanewise(a, b, [](float x, float y) { return x + y; }); }
    friend Float4 operator-(Float4 a, Float4 b) { return lanewise(a, b, [](float x, float y) { return x - y; }); }
    friend Float4 operator*(Float4 a, Float4 b) { return lanewise(a, b, [](float x, float y) { return x * y; }); }
    friend Float4 operator/(Float4 a, Float4 b) { return lanewise(a, b, [](float x, float y) { return x / y; }); }
    friend Float4 operator-(Float4 a) { return lanewise(a, a, [](float x, float) { return -x; }); }
    Float4& operator+=(Float4 b) { return *this = *this + b; }

    friend Mask4 operator>(Float4 a, Float4 b) { return compare(a, b, [](float x, float y) { return x > y; }); }
    friend Mask4 operator!=(Float4 a, Float4 b) { return compare(a, b, [](float x, float y) { return x != y; }); }
};

inline Float4 min(Float4 a, Float4 b) { return Float4::lanewise(a, b, [](float x, float y) { return min(x, y); }); }
inline Float4 max(Float4 a, Float4 b) { return Float4::lanewise(a, b, [](float x, float y) { return max(x, y); }); }
inline Float4 sqrt(Float4 a) { return Float4::lanewise(a, a, [](float x, float) { return std::sqrt(x); }); }
inline Float4 select(Mask4 mask, Float4 ifTrue, Float4 ifFalse) {
    Float4 r;
    for (int i = 0; i < 4; ++i) r.v[i] = mask.m[i] ? ifTrue.v[i] : ifFalse.v[i];
    return r;
}
inline Mask4 operator|(Mask4 a, Mask4 b) { return {{a.m[0] || b.m[0], a.m[1] || b.m[1], a.m[2] || b.m[2], a.m[3] || b.m[3]}}; }
inline unsigned laneBits(Mask4 mask) { return (mask.m[0] ? 1u : 0u) | (mask.m[1] ? 2u : 0u) | (mask.m[2] ? 4u : 0u) | (mask.m[3] ? 8u : 0u); }
inline bool noLane(Mask4 mask) { return !(mask.m[0] || mask.m[1] || mask.m[2] || mask.m[3]); }
inline bool allLanes(Mask4 mask) { return mask.m[0] && mask.m[1] && mask.m[2] && mask.m[3]; }

// Rows to columns: afterwards lane i of m[j] is what lane j of m[i] was.
inline void transpose(Float4 (&m)[4]) {
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) std::swap(m[i].v[j], m[j].v[i]);
}

#endif

// The mask type that comparisons of F give: bool for float, Mask4 for Float4.
template <class F>
using MaskOf = decltype(F{} > F{});

// x limited to [lo, hi] (lo ≤ hi), lane by lane.
template <class F>
F clamp(F x, F lo, F hi) {
    return min(max(x, lo), hi);
}

}  // namespace perpdot::simd
