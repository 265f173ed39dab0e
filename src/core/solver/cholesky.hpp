// Cholesky factorisation K = L Lᵀ of a symmetric positive definite n x n system in double
// precision, on K's envelope: the direct solves of joint trees (joint_tree.hpp, dense) and
// contact groups (contact_groups.hpp, banded). Row r of the lower triangle is zero left of its
// first column f_r, and Cholesky fills only inside that envelope, so L keeps it and the factor
// costs Σ_r p_r²/2 multiply-adds, p_r = r − f_r + 1 the row's profile: n³/6 dense, about n b²/2
// for a band of b rows.
//
// A shape says where each row starts and where its entries are stored: entry (r, c), f_r ≤ c ≤ r,
// at origin(r) + c; last(c) is the last row whose envelope reaches column c.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

namespace perpdot {

// Every row from column 0, n x n row-major (the upper triangle left alone).
struct DenseShape {
    int n;
    int first(int) const { return 0; }
    int last(int) const { return n - 1; }
    ptrdiff_t origin(int r) const { return static_cast<ptrdiff_t>(r) * n; }
};

// Rows stored one after another, each from its first column to its diagonal: row r's diagonal at
// diagonal[r] (envelopeLayout), its first column firstColumn[r], lastRow from envelopeLastRows.
struct EnvelopeShape {
    int n;
    const int* firstColumn;
    const int* lastRow;
    const size_t* diagonal;
    int first(int r) const { return firstColumn[r]; }
    int last(int c) const { return lastRow[c]; }
    ptrdiff_t origin(int r) const { return static_cast<ptrdiff_t>(diagonal[r]) - r; }
};

// Each row's diagonal offset from its first column; returns the envelope's size.
inline size_t envelopeLayout(const int* first, int n, size_t* diagonal) {
    size_t size = 0;
    for (int r = 0; r < n; ++r) {
        size += static_cast<size_t>(r - first[r] + 1);
        diagonal[r] = size - 1;
    }
    return size;
}

// last[c] = the last row r with first[r] ≤ c (at least c).
inline void envelopeLastRows(const int* first, int n, int* last) {
    for (int c = 0; c < n; ++c) last[c] = c;
    for (int r = 0; r < n; ++r)
        if (last[first[r]] < r) last[first[r]] = r;
    for (int c = 1; c < n; ++c)
        if (last[c] < last[c - 1]) last[c] = last[c - 1];
}

// Σ_r p_r²: twice the factor's multiply-adds.
inline int64_t envelopeCost(const int* first, int n) {
    int64_t cost = 0;
    for (int r = 0; r < n; ++r) cost += static_cast<int64_t>(r - first[r] + 1) * (r - first[r] + 1);
    return cost;
}

// Row r of the symmetric K, column by column in increasing order: f(s, K_rs) for every s in the
// envelope of row r or of column r.
template <class Shape, class F>
void forEachInRow(const double* K, const Shape& shape, int r, F&& f) {
    for (int s = shape.first(r); s <= r; ++s) f(s, K[shape.origin(r) + s]);
    for (int k = r + 1; k <= shape.last(r); ++k)
        if (shape.first(k) <= r) f(k, K[shape.origin(k) + r]);
}

// In-place Cholesky of K's envelope, row by row: L_rc = (K_rc − Σ_k L_rk L_ck) / L_cc over the
// columns both rows reach; false if K is not positive definite.
template <class Shape>
bool choleskyFactor(double* K, const Shape& shape) {
    for (int r = 0; r < shape.n; ++r) {
        const int fr = shape.first(r);
        double* Lr = K + shape.origin(r);
        for (int c = fr; c <= r; ++c) {
            const double* Lc = K + shape.origin(c);
            double s = Lr[c];
            for (int k = fr > shape.first(c) ? fr : shape.first(c); k < c; ++k) s -= Lr[k] * Lc[k];
            if (c < r) {
                Lr[c] = s / Lc[c];
            } else {
                if (!(s > 0.0)) return false;
                Lr[r] = std::sqrt(s);
            }
        }
    }
    return true;
}

// x ← K⁻¹ x from the factor: L y = x, then Lᵀ x = y.
template <class Shape>
void choleskySolve(const double* L, const Shape& shape, double* x) {
    for (int r = 0; r < shape.n; ++r) {
        const double* Lr = L + shape.origin(r);
        for (int k = shape.first(r); k < r; ++k) x[r] -= Lr[k] * x[k];
        x[r] /= Lr[r];
    }
    for (int r = shape.n - 1; r >= 0; --r) {
        for (int k = r + 1; k <= shape.last(r); ++k)
            if (shape.first(k) <= r) x[r] -= L[shape.origin(k) + r] * x[k];
        x[r] /= L[shape.origin(r) + r];
    }
}

}  // namespace perpdot
