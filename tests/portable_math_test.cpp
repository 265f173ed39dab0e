// perpdot::sinCos, atan2 and exp (include/perpdot/portable_math.hpp) against long double
// references: the error, in units of the float spacing at the true value, stays within the bound
// the header documents over many sampled inputs of every magnitude; the exact properties the
// header promises (odd sine, even cosine, signed zeros, the C standard's special cases) hold bit for bit.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

#include "perpdot/math.hpp"
#include "perpdot/portable_math.hpp"

namespace perpdot {
namespace {

constexpr float inf = std::numeric_limits<float>::infinity();
constexpr float nan = std::numeric_limits<float>::quiet_NaN();
constexpr float denormMin = std::numeric_limits<float>::denorm_min();
constexpr long double piL = std::numbers::pi_v<long double>;

// |got − ref| over the float spacing at ref (the subnormal spacing 2^−149 at the bottom).
long double ulpError(float got, long double ref) {
    int e = 0;
    std::frexp(std::fabs(ref), &e);  // |ref| = f 2^e, f ∈ [0.5, 1)
    const long double spacing = std::ldexp(1.0L, std::max(e - 24, -149));
    return std::fabs(static_cast<long double>(got) - ref) / spacing;
}

// Deterministic float samples: uniform bit patterns between two positive floats (so every binade
// in between is sampled alike), both signs.
std::vector<float> samples(float lo, float hi, int count) {
    std::vector<float> out;
    const std::uint32_t a = std::bit_cast<std::uint32_t>(lo), b = std::bit_cast<std::uint32_t>(hi);
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    for (int i = 0; i < count; ++i) {
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        const auto x = std::bit_cast<float>(a + static_cast<std::uint32_t>((state >> 33) % (b - a + 1)));
        out.push_back(x);
        out.push_back(-x);
    }
    return out;
}

TEST(PortableMath, SinCosWithinTwoAndAHalfUlpForEveryMagnitude) {
    std::vector<float> xs = samples(denormMin, std::numeric_limits<float>::max(), 200000);
    const std::vector<float> small = samples(1.0e-3f, 100.0f, 200000);
    xs.insert(xs.end(), small.begin(), small.end());
    // The floats nearest multiples of π/2, where the reduction cancels most: r is tiny there.
    for (int k = 1; k < 20000; ++k) {
        const float x = static_cast<float>(static_cast<long double>(k) * piL / 2);
        float y = std::nextafter(x, 0.0f);
        for (int n = 0; n < 3; ++n, y = std::nextafter(y, inf)) xs.push_back(y);
    }
    long double worstSin = 0, worstCos = 0;
    for (const float x : xs) {
        const SinCos sc = sinCos(x);
        worstSin = std::max(worstSin, ulpError(sc.sin, std::sin(static_cast<long double>(x))));
        worstCos = std::max(worstCos, ulpError(sc.cos, std::cos(static_cast<long double>(x))));
    }
    EXPECT_LE(worstSin, 2.5L);
    EXPECT_LE(worstCos, 2.5L);
}

TEST(PortableMath, SinIsOddAndCosEvenBitForBit) {
    for (const float x : samples(denormMin, 1.0e30f, 50000)) {
        const SinCos plus = sinCos(x), minus = sinCos(-x);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(minus.sin), std::bit_cast<std::uint32_t>(-plus.sin)) << x;
        ASSERT_EQ(std::bit_cast<std::uint32_t>(minus.cos), std::bit_cast<std::uint32_t>(plus.cos)) << x;
        ASSERT_LE(std::fabs(plus.sin), 1.0f);
        ASSERT_LE(std::fabs(plus.cos), 1.0f);
    }
}

TEST(PortableMath, SinCosSpecialValues) {
    EXPECT_EQ(std::bit_cast<std::uint32_t>(sinCos(0.0f).sin), 0u);
    EXPECT_TRUE(std::signbit(sinCos(-0.0f).sin));
    EXPECT_EQ(sinCos(-0.0f).sin, 0.0f);
    EXPECT_EQ(sinCos(0.0f).cos, 1.0f);
    EXPECT_EQ(sinCos(denormMin).sin, denormMin);  // sin x = x below the float resolution of x³/6
    EXPECT_EQ(sinCos(denormMin).cos, 1.0f);
    EXPECT_EQ(sinCos(1.0e-20f).sin, 1.0e-20f);
    for (const float x : {inf, -inf, nan}) {
        EXPECT_TRUE(std::isnan(sinCos(x).sin)) << x;
        EXPECT_TRUE(std::isnan(sinCos(x).cos)) << x;
    }
    // Huge angles: a full-precision reduction, so sin and cos still agree with the true values.
    const float huge = std::numeric_limits<float>::max();
    EXPECT_LE(ulpError(sinCos(huge).sin, std::sin(static_cast<long double>(huge))), 2.5L);
    EXPECT_LE(ulpError(sinCos(huge).cos, std::cos(static_cast<long double>(huge))), 2.5L);
    // Rot::fromAngle(0) is the identity exactly, and fromAngle is sinCos.
    EXPECT_EQ(Rot::fromAngle(0.0f), (Rot{1.0f, 0.0f}));
    EXPECT_EQ(Rot::fromAngle(2.5f), (Rot{sinCos(2.5f).cos, sinCos(2.5f).sin}));
}

TEST(PortableMath, Atan2WithinThreeUlpInEveryQuadrant) {
    const std::vector<float> ys = samples(denormMin, std::numeric_limits<float>::max(), 300);
    const std::vector<float> xs = samples(1.0e-6f, 1.0e6f, 300);
    long double worst = 0;
    for (const float y : ys) {
        for (const float x : xs) {
            worst = std::max(worst, ulpError(atan2(y, x), std::atan2(static_cast<long double>(y), static_cast<long double>(x))));
            worst = std::max(worst, ulpError(atan2(x, y), std::atan2(static_cast<long double>(x), static_cast<long double>(y))));
        }
    }
    EXPECT_LE(worst, 3.0L);
}

TEST(PortableMath, Atan2SpecialValuesFollowTheCStandard) {
    const float pi = static_cast<float>(piL), halfPi = static_cast<float>(piL / 2);
    EXPECT_EQ(std::bit_cast<std::uint32_t>(atan2(0.0f, 0.0f)), 0u);
    EXPECT_TRUE(std::signbit(atan2(-0.0f, 0.0f)));
    EXPECT_EQ(atan2(0.0f, -0.0f), pi);
    EXPECT_EQ(atan2(-0.0f, -0.0f), -pi);
    EXPECT_EQ(atan2(0.0f, -1.0f), pi);
    EXPECT_EQ(atan2(-0.0f, -1.0f), -pi);
    EXPECT_EQ(atan2(1.0f, 0.0f), halfPi);
    EXPECT_EQ(atan2(-1.0f, -0.0f), -halfPi);
    EXPECT_EQ(atan2(inf, 1.0f), halfPi);
    EXPECT_EQ(atan2(1.0f, inf), 0.0f);
    EXPECT_EQ(atan2(1.0f, -inf), pi);
    EXPECT_EQ(atan2(inf, inf), static_cast<float>(piL / 4));
    EXPECT_EQ(atan2(-inf, -inf), static_cast<float>(-3 * piL / 4));
    EXPECT_EQ(atan2(denormMin, denormMin), static_cast<float>(piL / 4));
    EXPECT_TRUE(std::isnan(atan2(nan, 1.0f)));
    EXPECT_TRUE(std::isnan(atan2(1.0f, nan)));
    // Rot::angle inverts fromAngle in (−π, π] to the bounds of both.
    for (const float a : {-3.0f, -1.0f, 0.25f, 1.5f, 3.1f}) EXPECT_NEAR(Rot::fromAngle(a).angle(), a, 4.0e-7f);
}

TEST(PortableMath, ExpWithinOneUlpOverflowAndUnderflow) {
    std::vector<float> xs = samples(denormMin, 88.72f, 200000);
    const std::vector<float> near = samples(80.0f, 103.9f, 20000);  // the subnormal results below −87.3
    xs.insert(xs.end(), near.begin(), near.end());
    long double worst = 0;
    for (const float x : xs) {
        const long double ref = std::exp(static_cast<long double>(x));
        if (ref > std::numeric_limits<float>::max()) continue;
        worst = std::max(worst, ulpError(exp(x), ref));
    }
    EXPECT_LE(worst, 1.0L);
    EXPECT_EQ(exp(0.0f), 1.0f);
    EXPECT_EQ(exp(-0.0f), 1.0f);
    EXPECT_EQ(exp(89.0f), inf);  // e^89 > FLT_MAX
    EXPECT_EQ(exp(inf), inf);
    EXPECT_EQ(exp(-inf), 0.0f);
    EXPECT_EQ(exp(-200.0f), 0.0f);
    EXPECT_GT(exp(-103.0f), 0.0f);  // e^−103 ≈ 1.9 · 2^−149: the smallest subnormals
    EXPECT_TRUE(std::isnan(exp(nan)));
}

// The bits, not only the accuracy: sin, cos, atan2 and exp of 600,000 fixed inputs of every
// magnitude, folded into one FNV-1a hash, are the bits x86-64 gives. tests/cross_arch_hash.sh runs
// this test on ARM64 and 32-bit x86 too; a 1-ulp difference on one CPU (as GCC's x87 int64
// conversion once made in the reduction of large angles on i386) changes the hash.
TEST(PortableMath, SameBitsOnEveryCpu) {
    std::uint64_t hash = 0xCBF29CE484222325ull;
    auto fold = [&hash](float v) {
        const std::uint32_t bits = std::bit_cast<std::uint32_t>(v);
        for (int byte = 0; byte < 4; ++byte) hash = (hash ^ ((bits >> (8 * byte)) & 0xFFu)) * 0x100000001B3ull;
    };
    const std::vector<float> xs = samples(denormMin, std::numeric_limits<float>::max(), 100000);
    const std::vector<float> angles = samples(1.0e-3f, 1.0e4f, 100000);
    const std::vector<float> exps = samples(denormMin, 103.9f, 100000);
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const SinCos wide = sinCos(xs[i]), small = sinCos(angles[i]);
        fold(wide.sin), fold(wide.cos), fold(small.sin), fold(small.cos);
        fold(atan2(angles[i], xs[i])), fold(atan2(xs[i], angles[(i + 7) % angles.size()]));
        fold(exp(exps[i]));
    }
    EXPECT_EQ(hash, 0xFE1EA6D7071F63D6ull) << std::hex << "portable math fingerprint " << hash;
}

}  // namespace
}  // namespace perpdot
