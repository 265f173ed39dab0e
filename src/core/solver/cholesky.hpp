// Dense Cholesky factorisation of a symmetric positive definite n x n system, row-major, in double
// precision: the direct solves of revolute trees (joint_tree.hpp) and contact groups
// (contact_groups.hpp).
#pragma once

#include <cmath>

namespace perpdot {

// In-place Cholesky K = L Lᵀ of the n x n row-major K (lower triangle written); false if K is not
// positive definite.
inline bool choleskyFactor(double* K, int n) {
    for (int c = 0; c < n; ++c) {
        double d = K[c * n + c];
        for (int k = 0; k < c; ++k) d -= K[c * n + k] * K[c * n + k];
        if (!(d > 0.0)) return false;
        const double l = std::sqrt(d);
        K[c * n + c] = l;
        for (int r = c + 1; r < n; ++r) {
            double s = K[r * n + c];
            for (int k = 0; k < c; ++k) s -= K[r * n + k] * K[c * n + k];
            K[r * n + c] = s / l;
        }
    }
    return true;
}

// x ← K⁻¹ x from the factor: L y = x, then Lᵀ x = y.
inline void choleskySolve(const double* L, int n, double* x) {
    for (int r = 0; r < n; ++r) {
        for (int k = 0; k < r; ++k) x[r] -= L[r * n + k] * x[k];
        x[r] /= L[r * n + r];
    }
    for (int r = n - 1; r >= 0; --r) {
        for (int k = r + 1; k < n; ++k) x[r] -= L[k * n + r] * x[k];
        x[r] /= L[r * n + r];
    }
}

}  // namespace perpdot
