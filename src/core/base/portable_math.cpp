// perpdot's own sin, cos, atan2 and exp (include/perpdot/portable_math.hpp): float operations in a
// fixed order, compiled with -ffp-contract=off, so every CPU and C library gives the same bits.
#include "perpdot/portable_math.hpp"

#include "perpdot/math.hpp"

#include <bit>
#include <cstdint>
#include <limits>

namespace perpdot {
namespace {

constexpr float inf = std::numeric_limits<float>::infinity();

bool isNan(float x) { return x != x; }
float magnitude(float x) { return std::bit_cast<float>(std::bit_cast<std::uint32_t>(x) & 0x7FFFFFFFu); }
bool signBit(float x) { return (std::bit_cast<std::uint32_t>(x) >> 31) != 0; }
// 2ⁿ for −126 ≤ n ≤ 127, built from its exponent bits.
float pow2(int n) { return std::bit_cast<float>(static_cast<std::uint32_t>(n + 127) << 23); }

// |x| = quadrant · π/2 + r, |r| ≤ π/4 (to rounding).
struct Reduced {
    float r;
    std::uint32_t quadrant;
};

// Cody–Waite, for 0 ≤ x < 64, the angles a body usually has: k = round(x · 2/π) ≤ 41 and
// π/2 = p1 + p2 + p3 + p4 with p1, p2, p3 of at most 12 significant bits, so each k pᵢ but the
// last is exact, and 60 bits of π/2 leave x − k π/2 accurate where it cancels most.
Reduced reduceSmall(float x) {
    constexpr float twoOverPi = 0x1.45f306p-1f;
    constexpr float p1 = 0x1.92p+0f, p2 = 0x1.fb4p-12f, p3 = 0x1.444p-24f, p4 = 0x1.68c234p-39f;
    // x ≥ 0, so truncating x · 2/π + 0.5 rounds to nearest (halves up): exact and libm-free.
    const auto k = static_cast<std::uint32_t>(x * twoOverPi + 0.5f);  // NOLINT(bugprone-incorrect-roundings)
    const auto kf = static_cast<float>(k);
    return {(((x - kf * p1) - kf * p2) - kf * p3) - kf * p4, k};
}

// Payne–Hanek in integers, for x ≥ 64 (and right from π/4 on): x = m 2^e with a 24-bit integer m; x · 2/π mod 4 needs
// only the bits of 2/π from 2^−(e−1) on, 96 of them are taken, and m times them modulo 2^96 holds
// the quadrant in its top two bits and the fraction of a quarter turn below.
Reduced reduce(float x) {
    // 2/π in binary, 256 bits after the point, preceded by a zero word so that bit i (weight 2^−i)
    // sits at position i + 31 from the top of word 0.
    static constexpr std::uint32_t twoOverPiBits[9] = {0x00000000, 0xA2F9836E, 0x4E441529, 0xFC2757D1, 0xF534DDC0,
                                                        0xDB629599, 0x3C439041, 0xFE5163AB, 0xDEBBC561};
    const std::uint32_t bits = std::bit_cast<std::uint32_t>(x);
    const std::uint64_t m = (bits & 0x7FFFFFu) | 0x800000u;
    const int e = static_cast<int>(bits >> 23) - 150;  // x = m 2^e, e ≥ −24 here
    auto word = [](int position) {  // the 32 bits of 2/π from `position` on
        const int w = position / 32, shift = position % 32;
        const std::uint64_t pair = (std::uint64_t{twoOverPiBits[w]} << 32) | twoOverPiBits[w + 1];
        return static_cast<std::uint32_t>((pair << shift) >> 32);
    };
    const int start = e - 1 + 31;
    const std::uint64_t f0 = word(start), f1 = word(start + 32), f2 = word(start + 64);
    const std::uint64_t p2 = m * f2, p1 = m * f1, p0 = m * f0;
    const std::uint64_t lo = p2 + (p1 << 32);
    const auto hi = static_cast<std::uint32_t>(p0 + (p1 >> 32) + (lo < p2 ? 1u : 0u));
    // The fraction as a signed 64-bit count of 2^−64 quarter turns, rounded to the nearest quadrant.
    const std::uint64_t fraction = (std::uint64_t{hi} << 34) | (lo >> 30);
    const std::uint32_t quadrant = (hi >> 30) + static_cast<std::uint32_t>(fraction >> 63);
    const std::int64_t half = static_cast<std::int64_t>(fraction) >> 1;  // 2^−63 quarter turns
    // r = half · (π/2 · 2^−63), the count split into two floats and π/2 into two.
    constexpr float cHi = 0x1.921fb6p-63f, cLo = -0x1.777a5cp-88f;
    // rounded: on 32-bit x86 the int64 conversion goes through the x87 unit, and GCC would convert
    // its exact 64-bit value back below instead of the float (halfLo 0, the last bit lost).
    const float halfHi = detail::rounded(static_cast<float>(half));
    const auto halfLo = static_cast<float>(half - static_cast<std::int64_t>(halfHi));
    return {halfHi * cHi + (halfHi * cLo + halfLo * cHi), quadrant};
}

}  // namespace

SinCos sinCos(float x) {
    const float ax = magnitude(x);
    if (!(ax <= std::numeric_limits<float>::max())) return {x - x, x - x};  // NaN, or ±∞ − ±∞
    const Reduced red = ax < 0x1.921fb4p-1f ? Reduced{ax, 0} : ax < 64.0f ? reduceSmall(ax) : reduce(ax);  // below π/4: r = x
    const float r = red.r, z = r * r;
    // Minimax on [−π/4, π/4]: sin r = r + r z S(z), cos r = 1 − z/2 + z² C(z).
    const float s = r + r * z * (-1.6666654611e-1f + z * (8.3321608736e-3f + z * -1.9515295891e-4f));
    const float c = (z * z * (4.166664568298827e-2f + z * (-1.388731625493765e-3f + z * 2.443315711809948e-5f)) - 0.5f * z) + 1.0f;
    SinCos out;
    switch (red.quadrant & 3u) {
        case 0: out = {s, c}; break;
        case 1: out = {c, -s}; break;
        case 2: out = {-s, -c}; break;
        default: out = {-c, s}; break;
    }
    if (signBit(x)) out.sin = -out.sin;
    return out;
}

float atan2(float y, float x) {
    if (isNan(x) || isNan(y)) return x + y;
    constexpr float pio4Hi = 0x1.921fb6p-1f, pio4Lo = -0x1.777a5cp-26f;
    constexpr float pio2Hi = 0x1.921fb6p+0f, pio2Lo = -0x1.777a5cp-25f;
    constexpr float piHi = 0x1.921fb6p+1f, piLo = -0x1.777a5cp-24f;
    const float ax = magnitude(x), ay = magnitude(y);
    const float big = ax > ay ? ax : ay, small = ax > ay ? ay : ax;
    // t = small / big ∈ [0, 1]; 0/0 and finite/∞ lie on the axis, ∞/∞ on the diagonal.
    float t = 0.0f;
    if (small == inf) t = 1.0f;
    else if (big != inf && big != 0.0f) t = small / big;
    // atan t = t + t z P(z), z = t², on [0, tan π/8]; above, π/4 + atan((t − 1)/(t + 1)).
    auto atanSmall = [](float u) {
        const float z = u * u;
        return (((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z - 3.33329491539e-1f) * z * u + u;
    };
    const float at = t > 0x1.a827ap-2f ? pio4Hi + (pio4Lo + atanSmall((t - 1.0f) / (t + 1.0f))) : atanSmall(t);
    // The angle in [0, π] from the octant: π/2 ∓ at above the diagonal, at or π − at below.
    float a = at;
    if (ay > ax) a = signBit(x) ? pio2Hi + (pio2Lo + at) : pio2Hi + (pio2Lo - at);
    else if (signBit(x)) a = piHi + (piLo - at);
    return signBit(y) ? -a : a;
}

float exp(float x) {
    if (isNan(x)) return x + x;
    if (x > 89.0f) return inf;
    if (x < -104.0f) return 0.0f;  // below half the smallest subnormal
    // k = round(x / ln 2); r = x − k ln 2 with ln 2 = l1 + l2, l1 of 16 bits so k l1 is exact.
    constexpr float log2e = 0x1.715476p+0f, l1 = 0x1.62e4p-1f, l2 = 0x1.7f7d1cp-20f;
    const int k = static_cast<int>(x * log2e + (x < 0.0f ? -0.5f : 0.5f));
    const auto kf = static_cast<float>(k);
    const float r = (x - kf * l1) - kf * l2;
    // eʳ = 1 + r + r² P(r), minimax on [−ln 2/2, ln 2/2].
    const float p = (((((1.9875691500e-4f * r + 1.3981999507e-3f) * r + 8.3334519073e-3f) * r + 4.1665795894e-2f) * r +
                      1.6666665459e-1f) * r + 5.0000001201e-1f) * (r * r) + r + 1.0f;
    // p 2^k: two factors where 2^k alone is not a normal float, the last one rounding once.
    if (k > 127) return p * pow2(k - 1) * 2.0f;
    if (k < -126) return p * pow2(k + 64) * pow2(-64);
    return p * pow2(k);
}

Rot Rot::fromAngle(float angle) {
    const SinCos sc = sinCos(angle);
    return {sc.cos, sc.sin};
}

float Rot::angle() const { return atan2(s, c); }

}  // namespace perpdot
