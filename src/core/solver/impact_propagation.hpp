// Simultaneous impacts through chains of touching bodies (docs/stress.md, "Impacts through a
// chain"): before the substeps, each elastic contact between two moving bodies that meets this
// step takes Hecker's collision impulse on its own, one pair at a time in contact order, until no
// such contact approaches. A Newton's cradle passes its ball's speed down the row as the textbook's
// sequence of two-body impacts does; the substeps then find those contacts parting.
#pragma once

#include <vector>

#include "collide/collision.hpp"
#include "perpdot/world.hpp"

namespace perpdot {

struct StepContext;
struct SolverWorld;  // solver_world.hpp

// A manifold point of an elastic contact between two moving bodies (solver slots), as an impact
// reads it.
struct ImpactPoint {
    int constraint = 0, point = 0;  // which constraint and manifold point
    int slotA = 0, slotB = 0;
    Vec2 rA, rB, normal;  // anchors from the centres of mass, normal from A to B
    float separation = 0;
    float restitution = 0, friction = 0;
    float impactSpeed = 0;  // the fastest approach an impact here took this step (hit events); 0: none
};

// What propagateImpacts keeps between its sweeps (and reportHitEvents reads after the step).
struct Impacts {
    std::vector<ImpactPoint> points;  // in constraint order
    std::vector<int> lastKick;        // by solver slot: the last sweep that changed its velocity
};

// The impacts of this step (after the contact constraints are selected and their bodies' free
// velocities found): the solver states and free velocities of the bodies they hit change alike.
void propagateImpacts(const SolverWorld& world, const StepContext& ctx);

}  // namespace perpdot
