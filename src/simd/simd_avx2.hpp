// Float8: eight float lanes in one AVX register, for the contact rows solved eight constraints at
// a time. Included only by contact_solver_avx2.cpp, the one file compiled for AVX2: its types live
// in an unnamed namespace, so every template instantiated on them stays inside that file and no
// AVX2 code can stand in for a function the rest of the library calls on CPUs without AVX2.
//
// The same exactly rounded operations as Float4 (simd.hpp): every lane computes bit for bit what
// the scalar `float` rows compute, so results do not depend on the lane width.
#pragma once

#include <immintrin.h>

namespace perpdot::simd {
inline namespace {  // inline: qualified calls such as simd::min find these beside simd.hpp's overloads

struct Mask8 {
    __m256 m;
};

struct Float8 {
    __m256 v;

    Float8() : v(_mm256_setzero_ps()) {}
    Float8(float s) : v(_mm256_set1_ps(s)) {}  // implicit: a float broadcasts, as for Float4
    explicit Float8(__m256 m) : v(m) {}
    // Lanes 0–3 from `low`, 4–7 from `high`.
    static Float8 join(__m128 low, __m128 high) { return Float8(_mm256_set_m128(high, low)); }
    static Float8 load(const float* p) { return Float8(_mm256_loadu_ps(p)); }
    void store(float* p) const { _mm256_storeu_ps(p, v); }

    friend Float8 operator+(Float8 a, Float8 b) { return Float8(_mm256_add_ps(a.v, b.v)); }
    friend Float8 operator-(Float8 a, Float8 b) { return Float8(_mm256_sub_ps(a.v, b.v)); }
    friend Float8 operator*(Float8 a, Float8 b) { return Float8(_mm256_mul_ps(a.v, b.v)); }
    friend Float8 operator/(Float8 a, Float8 b) { return Float8(_mm256_div_ps(a.v, b.v)); }
    friend Float8 operator-(Float8 a) { return Float8(_mm256_xor_ps(a.v, _mm256_set1_ps(-0.0f))); }
    Float8& operator+=(Float8 b) { return *this = *this + b; }

    friend Mask8 operator>(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_GT_OQ)}; }
    friend Mask8 operator!=(Float8 a, Float8 b) { return {_mm256_cmp_ps(a.v, b.v, _CMP_NEQ_UQ)}; }
};

// vminps/vmaxps return the second operand when the comparison is false, as minps/maxps do.
inline Float8 min(Float8 a, Float8 b) { return Float8(_mm256_min_ps(a.v, b.v)); }
inline Float8 max(Float8 a, Float8 b) { return Float8(_mm256_max_ps(a.v, b.v)); }
inline Float8 sqrt(Float8 a) { return Float8(_mm256_sqrt_ps(a.v)); }
inline Float8 select(Mask8 mask, Float8 ifTrue, Float8 ifFalse) { return Float8(_mm256_blendv_ps(ifFalse.v, ifTrue.v, mask.m)); }

}  // namespace
}  // namespace perpdot::simd
