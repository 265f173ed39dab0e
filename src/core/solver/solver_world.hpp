// The solver's view of the world: the parts of World::Impl its stages read and write, and nothing
// else, built by World::step (step.cpp). A stage that needs two parts takes those parts
// (contactRows(contacts, bodies, ...), storeContactImpulses(contacts, cache)); the others, the
// joint stages among them (joint.hpp), take this view. Its parts keep World::Impl's names
// (w.contactCache, w.scratch.bodies): a view, passed as `const SolverWorld&`, whose parts are as
// writable as their references.
#pragma once

#include "core/base/pool.hpp"
#include "core/bodies/body_store.hpp"
#include "core/contacts/contact_cache.hpp"
#include "core/threads/workers.hpp"
#include "core/world/step_scratch.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

struct SolverWorld {
    const Pool<Body>& bodies;    // findContactGroups: whether a body is dynamic and has joints; prepareJoints: frames, masses
    ContactCache& contactCache;  // the touching contacts: their values into the rows, the impulses back
    JointStore& joints;          // the joints: their values into the prepared joints, the impulses back
    struct Scratch {             // the solver's parts of StepScratch
        SolverBodies& bodies;
        ContactScratch& contacts;
        GraphColoring& coloring;  // the joints' colours, which the contacts' continue
        JointScratch& joints;     // the joints' rows, solved colour by colour beside the contacts'
    } scratch;
    Workers& workers;
    Vec2 gravity;         // findContactGroups measures loads in g
    bool anyRestitution;  // some shape was ever elastic: propagateImpacts looks for impacts
};

}  // namespace perpdot
