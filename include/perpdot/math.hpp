/// @file
/// 2D vector algebra in Hecker's notation: perp, perpDot, and the velocity of a body point.
///
/// These functions are inline, so they compile with whatever flags the including code uses. Two
/// rules keep a world's bits independent of a game's flags (-ffast-math, -ffp-contract=fast, -O0):
///
/// - What the library computes, it computes out of line or inlined into its own code, compiled with
///   its own flags (-ffp-contract=off): Rot::fromAngle and Rot::angle are out of line
///   (portable_math.hpp), and the ctest `inline_math_inlined` checks that the library holds no
///   out-of-line copy of the functions below, which the linker could swap for a game's copy.
/// - Every product and sum below passes through detail::rounded, an empty asm statement the
///   optimiser cannot see through: a game's flags can neither fuse a product into a multiply-add
///   nor regroup a sum, so a position the game computes with rotate, transformPoint, dot, Vec2
///   operators ... is the same float under any flags (the ctest `consumer_flags` builds one game with
///   several flags and compares the state_hash). Plain float expressions the game writes itself,
///   such as `x0 + 1.1f * i`, are its own: compile the code that places bodies with
///   -ffp-contract=off if it must give the same world on every CPU. Linking with -ffast-math
///   flushes subnormals to zero process-wide (crtfastmath), which no header can undo: link
///   without it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

/// perpdot: the engine, its scenes and the cross-check against Box2D.
namespace perpdot {

namespace detail {
/// v, as a float the optimiser must take as it is: no instruction, but no contraction into a
/// multiply-add and no reassociation across it, whatever the flags of the code it is inlined into.
constexpr float rounded(float v) {
#if defined(__GNUC__)
    if (!std::is_constant_evaluated()) {
#if defined(__SSE_MATH__)
        asm("" : "+x"(v));
#elif defined(__aarch64__)
        asm("" : "+w"(v));
#else
        asm("" : "+m"(v));  // through memory: also rounds an x87 value to float
#endif
    }
#endif
    return v;
}
}  // namespace detail

/// A 2D vector (metres, m/s, newtons, ... by context).
struct Vec2 {
    float x = 0.0f;  ///< x component
    float y = 0.0f;  ///< y component

    /// a += b
    constexpr Vec2& operator+=(Vec2 b) { return *this = {detail::rounded(x + b.x), detail::rounded(y + b.y)}; }
    /// a -= b
    constexpr Vec2& operator-=(Vec2 b) { return *this = {detail::rounded(x - b.x), detail::rounded(y - b.y)}; }
    /// a *= s
    constexpr Vec2& operator*=(float s) { return *this = {detail::rounded(x * s), detail::rounded(y * s)}; }
    /// Exact component-wise equality.
    friend constexpr bool operator==(Vec2, Vec2) = default;
};

/// a + b
constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {detail::rounded(a.x + b.x), detail::rounded(a.y + b.y)}; }
/// a - b
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {detail::rounded(a.x - b.x), detail::rounded(a.y - b.y)}; }
/// -a
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
/// s a
constexpr Vec2 operator*(float s, Vec2 a) { return {detail::rounded(s * a.x), detail::rounded(s * a.y)}; }
/// a s
constexpr Vec2 operator*(Vec2 a, float s) { return s * a; }

/// a·b
constexpr float dot(Vec2 a, Vec2 b) { return detail::rounded(detail::rounded(a.x * b.x) + detail::rounded(a.y * b.y)); }

/// perp(r): r turned a quarter turn counter-clockwise.
constexpr Vec2 perp(Vec2 r) { return {-r.y, r.x}; }

/// perpDot(a, b) = perp(a)·b, the 2D "cross product"; torque is perpDot(r, F).
constexpr float perpDot(Vec2 a, Vec2 b) { return detail::rounded(detail::rounded(a.x * b.y) - detail::rounded(a.y * b.x)); }

/// v_B = v + ω perp(r): velocity of the body point at offset r from the centre of mass.
constexpr Vec2 pointVelocity(Vec2 v, float omega, Vec2 r) { return v + omega * perp(r); }

/// |a|²
inline float lengthSquared(Vec2 a) { return dot(a, a); }
/// |a|
inline float length(Vec2 a) { return detail::rounded(std::sqrt(dot(a, a))); }  // never an rsqrt estimate
/// |b - a|
inline float distance(Vec2 a, Vec2 b) { return length(b - a); }

/// Unit vector along a, or zero when a is (nearly) zero.
inline Vec2 normalize(Vec2 a) {
    const float len = length(a);
    return len > 1.0e-12f ? detail::rounded(1.0f / len) * a : Vec2{};
}

/// Neither NaN nor infinite.
inline bool isFinite(float a) { return std::isfinite(a); }
/// Both components finite.
inline bool isFinite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }

/// A rotation stored as cos/sin of its angle.
struct Rot {
    float c = 1.0f;  ///< cos θ
    float s = 0.0f;  ///< sin θ

    /// The rotation by `angle` radians, counter-clockwise: perpdot::sinCos, out of line, so the
    /// same bits on every CPU, C library and compiler flags (portable_math.hpp).
    static Rot fromAngle(float angle);
    /// θ = perpdot::atan2(s, c), in [-π, π]; out of line like fromAngle.
    float angle() const;
    /// Exact equality of c and s.
    friend constexpr bool operator==(Rot, Rot) = default;
};

/// q v: v turned by q.
constexpr Vec2 rotate(Rot q, Vec2 v) { return {perpDot({q.c, q.s}, {v.y, v.x}), dot({q.s, q.c}, v)}; }
/// q⁻¹ v: v turned back by q.
constexpr Vec2 invRotate(Rot q, Vec2 v) { return {dot({q.c, q.s}, v), perpDot({q.c, q.s}, v)}; }
/// q * r: apply r, then q.
constexpr Rot mul(Rot q, Rot r) {
    const Vec2 v = rotate(q, {r.c, r.s});
    return {v.x, v.y};
}
/// q⁻¹ * r: the rotation from frame q to frame r.
constexpr Rot invMul(Rot q, Rot r) {
    const Vec2 v = invRotate(q, {r.c, r.s});
    return {v.x, v.y};
}

/// A body frame: origin position p and rotation q.
struct Transform {
    Vec2 p{};  ///< origin, world frame
    Rot q{}; ///< rotation from the body frame to the world frame
    /// Exact equality of p and q.
    friend constexpr bool operator==(const Transform&, const Transform&) = default;
};

/// A body-frame point in the world frame: q local + p.
constexpr Vec2 transformPoint(const Transform& t, Vec2 local) { return rotate(t.q, local) + t.p; }
/// A world point in the body frame: q⁻¹ (world - p).
constexpr Vec2 invTransformPoint(const Transform& t, Vec2 world) { return invRotate(t.q, world - t.p); }

/// An axis-aligned bounding box.
struct AABB {
    Vec2 lower{};  ///< smallest x and y
    Vec2 upper{};  ///< largest x and y
};

/// Whether two boxes overlap (touching counts).
constexpr bool overlaps(const AABB& a, const AABB& b) {
    return !(b.lower.x > a.upper.x || b.lower.y > a.upper.y || a.lower.x > b.upper.x || a.lower.y > b.upper.y);
}

/// The smallest box holding both boxes.
constexpr AABB combine(const AABB& a, const AABB& b) {
    return {{std::min(a.lower.x, b.lower.x), std::min(a.lower.y, b.lower.y)},
            {std::max(a.upper.x, b.upper.x), std::max(a.upper.y, b.upper.y)}};
}

/// π as a float.
inline constexpr float pi = 3.14159265359f;

}  // namespace perpdot
