/// @file
/// sin, cos, atan2 and exp that give the same bits on every CPU, compiler and C library.
///
/// The C library's `sinf`, `cosf`, `atan2f` and `expf` are not specified to the last bit: glibc's
/// `atan2f` differs by one ulp between its x86-64 and ARM64 builds on about 0.1 % of inputs, and a
/// new C library version may change any of them. A body's rotation is `Rot::fromAngle` of its angle
/// every step, so one such ulp changes a world's future. perpdot therefore computes these functions
/// itself, out of line in the library (built with `-ffp-contract=off`), in float arithmetic only
/// (no long double, no fused multiply-add), each operation in a fixed order:
///
/// - sinCos: |x| = k π/2 + r, |r| ≤ π/4: below 64 by Cody–Waite with π/2 in four parts (60 bits),
///   above by Payne–Hanek in 64-bit integers with 96 bits of 2/π (exact enough for every float,
///   however large); then minimax polynomials of degree 3 in r².
/// - atan2: the octant by comparisons, atan(t) for t = min/max ≤ 1 (t > tan π/8 through
///   π/4 + atan((t−1)/(t+1))), a minimax polynomial of degree 4 in t².
/// - exp: x = k ln 2 + r, |r| ≤ ln 2 / 2, a degree-6 polynomial, then 2^k by the exponent bits.
///
/// Accuracy, measured against long double references (tests/portable_math_test.cpp):
/// sinCos ≤ 2.5 ulp for every finite float, huge angles included; atan2 ≤ 3 ulp; exp ≤ 1 ulp,
/// subnormal results included (errors in units of the float spacing at the true result). Exact properties: sin(−x) = −sin(x) and
/// cos(−x) = cos(x) bit for bit, sinCos(±0) = (±0, 1), |sin|, |cos| ≤ 1, atan2 gives the C standard's
/// signed zeros, ±π, ±π/2 and ±π/4, ±3π/4 for the zero and infinite cases, exp(−∞) = 0, exp(+∞) = +∞;
/// NaN in gives NaN out, and sinCos(±∞) is NaN.
#pragma once

namespace perpdot {

/// sin x and cos x of one angle.
struct SinCos {
    float sin = 0.0f;  ///< sin x
    float cos = 1.0f;  ///< cos x
};

/// sin x and cos x, x in radians; bit-identical everywhere, ≤ 2.5 ulp.
SinCos sinCos(float x);
/// The angle of (x, y) from the +x axis, in [−π, π]; bit-identical everywhere, ≤ 3 ulp.
float atan2(float y, float x);
/// eˣ; bit-identical everywhere, ≤ 1 ulp.
float exp(float x);

}  // namespace perpdot
