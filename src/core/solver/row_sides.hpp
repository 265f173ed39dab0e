// A row of a block solved directly (contact groups, contact_groups.hpp; joint trees,
// joint_tree.hpp) by the bodies it moves, and the entries of K = J M⁻¹ Jᵀ between two rows.
#pragma once

#include <array>

#include "perpdot/math.hpp"

namespace perpdot {

// One side of a row: J's entries for the body in solver slot `slot` (lin·v + ang·ω), with the
// body's inverse mass and inertia. A body that cannot move has zero inverse mass and inertia.
struct RowSide {
    int slot;
    Vec2 lin;
    float ang, invMass, invInertia;
};

// K_rs = Σ over the bodies rows r and s share: lin_r·lin_s / m + ang_r ang_s / I.
inline double coupling(const std::array<RowSide, 2>& r, const std::array<RowSide, 2>& s) {
    double k = 0.0;
    for (const RowSide& p : r)
        for (const RowSide& q : s)
            if (p.slot == q.slot && p.slot != 0)
                k += static_cast<double>(p.invMass) * dot(p.lin, q.lin) + static_cast<double>(p.invInertia) * p.ang * q.ang;
    return k;
}

}  // namespace perpdot
