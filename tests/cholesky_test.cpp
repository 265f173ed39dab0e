// The Cholesky factor on an envelope (src/core/solver/cholesky.hpp): on a banded SPD matrix whose
// rows start at different columns, the envelope factor and solve give the dense ones' numbers bit
// for bit (they skip only products with L's zeros outside the envelope), and solve K x = b.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/solver/cholesky.hpp"

namespace perpdot {
namespace {

constexpr int n = 40;

// Row r's first column: a band of 1 to 4 rows, uneven, and a row reaching back to column 0.
int firstOf(int r) { return r == 30 ? 0 : std::max(0, r - 1 - (r * 7) % 4); }

// K_rc inside the envelope, diagonally dominant: symmetric positive definite.
double entry(int r, int c) { return r == c ? 10.0 + 0.1 * r : std::sin(1.0 + r * 3.0 + c * 0.7); }

struct Envelope {
    std::vector<int> first, last;
    std::vector<size_t> diagonal;
    std::vector<double> K;
    EnvelopeShape shape() const { return {n, first.data(), last.data(), diagonal.data()}; }
};

Envelope banded() {
    Envelope e{std::vector<int>(n), std::vector<int>(n), std::vector<size_t>(n), {}};
    for (int r = 0; r < n; ++r) e.first[r] = firstOf(r);
    envelopeLastRows(e.first.data(), n, e.last.data());
    e.K.resize(envelopeLayout(e.first.data(), n, e.diagonal.data()));
    for (int r = 0; r < n; ++r)
        for (int c = e.first[r]; c <= r; ++c) e.K[e.shape().origin(r) + c] = entry(r, c);
    return e;
}

std::vector<double> dense() {  // the same K, every entry stored, zeros outside the envelope
    std::vector<double> K(n * n, 0.0);
    for (int r = 0; r < n; ++r)
        for (int c = firstOf(r); c <= r; ++c) K[r * n + c] = K[c * n + r] = entry(r, c);
    return K;
}

std::vector<double> rightHandSide() {
    std::vector<double> b(n);
    for (int r = 0; r < n; ++r) b[r] = std::cos(0.3 * r) - 0.5;
    return b;
}

TEST(EnvelopeCholesky, LastRowsReachEachColumn) {
    const Envelope e = banded();
    for (int c = 0; c < n; ++c) {
        int last = c;
        for (int r = c; r < n; ++r)
            if (e.first[r] <= c) last = r;
        EXPECT_EQ(e.last[c], last) << "column " << c;
    }
}

TEST(EnvelopeCholesky, MatchesTheDenseFactorOnABandedMatrix) {
    Envelope e = banded();
    std::vector<double> K = dense();
    ASSERT_TRUE(choleskyFactor(K.data(), DenseShape{n}));
    ASSERT_TRUE(choleskyFactor(e.K.data(), e.shape()));
    for (int r = 0; r < n; ++r) {
        for (int c = 0; c < e.first[r]; ++c) EXPECT_EQ(K[r * n + c], 0.0) << r << ", " << c << ": fill outside the envelope";
        for (int c = e.first[r]; c <= r; ++c) EXPECT_EQ(K[r * n + c], e.K[e.shape().origin(r) + c]) << r << ", " << c;
    }
    std::vector<double> xDense = rightHandSide(), xEnvelope = rightHandSide();
    choleskySolve(K.data(), DenseShape{n}, xDense.data());
    choleskySolve(e.K.data(), e.shape(), xEnvelope.data());
    EXPECT_EQ(xDense, xEnvelope);
    // K x = b, with K's rows read from the envelope as the contact groups read them.
    const Envelope unfactored = banded();
    const std::vector<double> b = rightHandSide();
    for (int r = 0; r < n; ++r) {
        double Kx = 0.0;
        forEachInRow(unfactored.K.data(), unfactored.shape(), r, [&](int s, double k) { Kx += k * xEnvelope[s]; });
        EXPECT_NEAR(Kx, b[r], 1e-12) << "row " << r;
    }
}

TEST(EnvelopeCholesky, RefusesAnIndefiniteMatrix) {
    Envelope e = banded();
    e.K[e.diagonal[20]] = -1.0;
    EXPECT_FALSE(choleskyFactor(e.K.data(), e.shape()));
}

}  // namespace
}  // namespace perpdot
