// The linear complementarity problem of a block of rows solved directly (contact groups,
// contact_groups.hpp; joint trees with limits, joint_tree.hpp): K Δλ − y = w, where a one-sided
// row keeps λ + Δλ ≥ 0, w ≥ 0 and (λ + Δλ)·w = 0 (it either pushes or is left separating faster
// than its target) and a free row (an equality) keeps w = 0, λ of either sign. K is stored on its
// envelope (cholesky.hpp) and factored into L beforehand; block principal pivoting (Júdice and
// Pires) factors the pushing rows' K_AA on the same envelope at each pivot.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/solver/cholesky.hpp"

namespace perpdot {

// The problem's vectors, by row, and the pivoting's scratch, kept to reuse their memory: λ before
// the solve and y are the inputs, x = Δλ the output.
struct Complementarity {
    std::vector<double> lambda, y, x, rhs, activeK;
    std::vector<int> activeIndex, activeFirst, activeLast;
    std::vector<size_t> activeDiagonal;
    std::vector<uint8_t> active;
    // Room for `rows` rows and an envelope of `envelope` entries.
    void reserve(int rows, size_t envelope);
};

// Principal pivots of a solve at most; false when it needs more, or K_AA does not factor.
inline constexpr int maxPivots = 8;

bool solveComplementarity(Complementarity& lcp, const EnvelopeShape& shape, const double* K, const double* L, const uint8_t* freeRow);

}  // namespace perpdot
