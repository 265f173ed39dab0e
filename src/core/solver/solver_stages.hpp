// The substeps of World::step as a list of stages — once, the contact blocks laid out; per substep
// its forces, then per pass the joint and contact rows colour by colour, and x += hs v between
// the solve and the relax — run in order
// by every worker at once. The items of a stage share no moving body (graph colouring), so
// workers claim them in any order: worker k of n starts at item k/n of every stage and goes
// forward, then back from there, so the same worker keeps about the same bodies from stage to
// stage (their states stay in its cache); a worker leaves a stage when all its items are done. Nobody
// waits for a worker that has not started, so any worker count, and any task system that runs
// the workers late or one after another, gives the same result.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/world/step_context.hpp"

namespace perpdot {

struct SolverWorld;  // solver_world.hpp

struct SolverStage {
    enum class Work : uint8_t { LayOutContacts, SubstepForces, Joints, SerialJoints, Contacts, SerialContacts, ContactGroups, IntegratePositions, StoreContacts };
    Work work = Work::SubstepForces;
    RowPass pass = RowPass::WarmStart;
    int color = 0;
    int units = 0;          // bodies, joint units or contact blocks
    int unitsPerItem = 1;   // a worker claims this many at a time
    int items() const { return (units + unitsPerItem - 1) / unitsPerItem; }
};

class SolverStages {
public:
    // The stages of one substep for this step's colours (after colorJoints and prepareContactBlocks),
    // after those run once before the substeps (the contact blocks laid out, colour by colour, by
    // the workers that solve them), and those run once after: restitution's, then the contact
    // blocks' impulses stored (by the workers that solved them last).
    void build(const SolverWorld& w);
    // Every substep's stages, on the world's workers.
    void run(const SolverWorld& w, const StepContext& ctx);

private:
    struct alignas(64) Sync {  // a stage of a substep: its items done
        std::atomic<int> done{0};
    };
    void execute(const SolverWorld& w, const StepContext& ctx, const SolverStage& stage, int begin, int end) const;
    void participate(const SolverWorld& w, const StepContext& ctx, int worker, int workerCount);

    // stages_[0, firstSubstepStage_) run once before the substeps, [firstSubstepStage_,
    // substepStages_) every substep, the rest (restitution) once after the last.
    std::vector<SolverStage> stages_;
    size_t firstSubstepStage_ = 0, substepStages_ = 0;
    std::vector<int> firstClaim_;  // by stage: its first item's claim in claims_
    std::unique_ptr<Sync[]> sync_;
    size_t syncCapacity_ = 0;
    // By item of every stage: how many substeps have claimed it (the claim of substep k turns k into k + 1).
    std::unique_ptr<std::atomic<int>[]> claims_;
    size_t claimCapacity_ = 0;
};

}  // namespace perpdot
