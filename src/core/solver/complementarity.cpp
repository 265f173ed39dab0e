#include "core/solver/complementarity.hpp"

#include <algorithm>

namespace perpdot {
namespace {

// A dropped row approaching faster than its target by less than this (m/s) counts as separating.
constexpr double separationTolerance = 1e-6;

}  // namespace

void Complementarity::reserve(int rows, size_t envelope) {
    const size_t n = static_cast<size_t>(rows);
    for (std::vector<double>* v : {&lambda, &y, &x, &rhs}) v->resize(std::max(v->size(), n));
    for (std::vector<int>* v : {&activeIndex, &activeFirst, &activeLast}) v->resize(std::max(v->size(), n));
    activeDiagonal.resize(std::max(activeDiagonal.size(), n));
    active.resize(std::max(active.size(), n));
    activeK.resize(std::max(activeK.size(), envelope));
}

// Start with every row pushing, solve K_AA Δλ_A = y_A + K_AI λ_I for the pushing rows A (the
// others drop to λ = 0), then flip every row that breaks its condition and solve again.
bool solveComplementarity(Complementarity& lcp, const EnvelopeShape& shape, const double* K, const double* L, const uint8_t* freeRow) {
    const int n = shape.n;
    std::copy(lcp.y.begin(), lcp.y.begin() + n, lcp.x.begin());
    choleskySolve(L, shape, lcp.x.data());
    std::fill(lcp.active.begin(), lcp.active.begin() + n, 1);
    for (int pivot = 0; pivot < maxPivots; ++pivot) {
        bool flipped = false;
        for (int r = 0; r < n; ++r) {
            if (lcp.active[r]) {
                if (!freeRow[r] && lcp.lambda[r] + lcp.x[r] < 0.0) lcp.active[r] = 0, flipped = true;
                continue;
            }
            double w = -lcp.y[r];
            forEachInRow(K, shape, r, [&](int s, double k) { w += k * lcp.x[s]; });
            if (w < -separationTolerance) lcp.active[r] = 1, flipped = true;
        }
        if (!flipped) return true;
        // K_AA keeps K's envelope: an active row starts at the first active column of its own.
        int m = 0;
        for (int c = 0; c < n; ++c) {
            lcp.activeIndex[c] = m;
            m += lcp.active[c];
        }
        size_t entry = 0;
        for (int r = 0; r < n; ++r) {
            if (!lcp.active[r]) continue;
            const int i = lcp.activeIndex[r];
            lcp.activeFirst[i] = lcp.activeIndex[shape.first(r)];
            lcp.rhs[i] = lcp.y[r];
            forEachInRow(K, shape, r, [&](int s, double k) {
                if (!lcp.active[s])
                    lcp.rhs[i] += k * lcp.lambda[s];
                else if (s <= r)
                    lcp.activeK[entry++] = k;
            });
        }
        envelopeLayout(lcp.activeFirst.data(), m, lcp.activeDiagonal.data());
        envelopeLastRows(lcp.activeFirst.data(), m, lcp.activeLast.data());
        const EnvelopeShape active{m, lcp.activeFirst.data(), lcp.activeLast.data(), lcp.activeDiagonal.data()};
        if (!choleskyFactor(lcp.activeK.data(), active)) return false;
        choleskySolve(lcp.activeK.data(), active, lcp.rhs.data());
        for (int r = 0, i = 0; r < n; ++r) lcp.x[r] = lcp.active[r] ? lcp.rhs[i++] : -lcp.lambda[r];
    }
    return false;
}

}  // namespace perpdot
