/// @file
/// 2D vector algebra in Hecker's notation: perp, perpDot, and the velocity of a body point.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

/// perpdot: the engine, its scenes and the cross-check against Box2D.
namespace perpdot {

/// A 2D vector (metres, m/s, newtons, ... by context).
struct Vec2 {
    float x = 0.0f;  ///< x component
    float y = 0.0f;  ///< y component

    /// a += b
    constexpr Vec2& operator+=(Vec2 b) { x += b.x; y += b.y; return *this; }
    /// a -= b
    constexpr Vec2& operator-=(Vec2 b) { x -= b.x; y -= b.y; return *this; }
    /// a *= s
    constexpr Vec2& operator*=(float s) { x *= s; y *= s; return *this; }
    /// Exact component-wise equality.
    friend constexpr bool operator==(Vec2, Vec2) = default;
};

/// a + b
constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
/// a - b
constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
/// -a
constexpr Vec2 operator-(Vec2 a) { return {-a.x, -a.y}; }
/// s a
constexpr Vec2 operator*(float s, Vec2 a) { return {s * a.x, s * a.y}; }
/// a s
constexpr Vec2 operator*(Vec2 a, float s) { return {s * a.x, s * a.y}; }

/// a·b
constexpr float dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }

/// perp(r): r turned a quarter turn counter-clockwise.
constexpr Vec2 perp(Vec2 r) { return {-r.y, r.x}; }

/// perpDot(a, b) = perp(a)·b, the 2D "cross product"; torque is perpDot(r, F).
constexpr float perpDot(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }

/// v_B = v + ω perp(r): velocity of the body point at offset r from the centre of mass.
constexpr Vec2 pointVelocity(Vec2 v, float omega, Vec2 r) { return {v.x - omega * r.y, v.y + omega * r.x}; }

/// |a|²
inline float lengthSquared(Vec2 a) { return dot(a, a); }
/// |a|
inline float length(Vec2 a) { return std::sqrt(dot(a, a)); }
/// |b - a|
inline float distance(Vec2 a, Vec2 b) { return length(b - a); }

/// Unit vector along a, or zero when a is (nearly) zero.
inline Vec2 normalize(Vec2 a) {
    const float len = length(a);
    return len > 1.0e-12f ? (1.0f / len) * a : Vec2{};
}

/// Neither NaN nor infinite.
inline bool isFinite(float a) { return std::isfinite(a); }
/// Both components finite.
inline bool isFinite(Vec2 a) { return std::isfinite(a.x) && std::isfinite(a.y); }

/// A rotation stored as cos/sin of its angle.
struct Rot {
    float c = 1.0f;  ///< cos θ
    float s = 0.0f;  ///< sin θ

    /// The rotation by `angle` radians, counter-clockwise.
    static Rot fromAngle(float angle) { return {std::cos(angle), std::sin(angle)}; }
    /// θ = atan2(s, c), in (-π, π].
    float angle() const { return std::atan2(s, c); }
    /// Exact equality of c and s.
    friend constexpr bool operator==(Rot, Rot) = default;
};

/// q v: v turned by q.
constexpr Vec2 rotate(Rot q, Vec2 v) { return {q.c * v.x - q.s * v.y, q.s * v.x + q.c * v.y}; }
/// q⁻¹ v: v turned back by q.
constexpr Vec2 invRotate(Rot q, Vec2 v) { return {q.c * v.x + q.s * v.y, -q.s * v.x + q.c * v.y}; }
/// q * r: apply r, then q.
constexpr Rot mul(Rot q, Rot r) { return {q.c * r.c - q.s * r.s, q.s * r.c + q.c * r.s}; }
/// q⁻¹ * r: the rotation from frame q to frame r.
constexpr Rot invMul(Rot q, Rot r) { return {q.c * r.c + q.s * r.s, q.c * r.s - q.s * r.c}; }

/// A body frame: origin position p and rotation q.
struct Transform {
    Vec2 p;  ///< origin, world frame
    Rot q;   ///< rotation from the body frame to the world frame
    /// Exact equality of p and q.
    friend constexpr bool operator==(const Transform&, const Transform&) = default;
};

/// A body-frame point in the world frame: q local + p.
constexpr Vec2 transformPoint(const Transform& t, Vec2 local) { return rotate(t.q, local) + t.p; }
/// A world point in the body frame: q⁻¹ (world - p).
constexpr Vec2 invTransformPoint(const Transform& t, Vec2 world) { return invRotate(t.q, world - t.p); }

/// An axis-aligned bounding box.
struct AABB {
    Vec2 lower;  ///< smallest x and y
    Vec2 upper;  ///< largest x and y
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
