#include "core/solver/solver_stages.hpp"

#include <algorithm>
#include <thread>

#include "core/bodies/integrate.hpp"
#include "core/joints/joint.hpp"
#include "core/solver/contact_groups.hpp"
#include "core/solver/contact_solver.hpp"

namespace perpdot {

namespace {

// Units per claim: enough work to outweigh the atomic claim, few enough to share a colour.
constexpr int bodiesPerItem = 256;
constexpr int jointUnitsPerItem = 32;
constexpr int contactsPerItem = 128;

}  // namespace

void SolverStages::build(const SolverWorld& w) {
    using Work = SolverStage::Work;
    stages_.clear();
    const int bodies = static_cast<int>(w.scratch.bodies.states.size()) - 1;
    auto add = [&](Work work, RowPass pass, int color, int units, int unitsPerItem) {
        if (units > 0) stages_.push_back({work, pass, color, units, unitsPerItem});
    };
    // A colour's contact blocks: every stage that touches them (layout, passes, store) claims the
    // same items, so a block stays with the worker that laid it out and solves it.
    auto addContactBlocks = [&](Work work, RowPass pass, int color) {
        add(work, pass, color, contactBlockCount(w.scratch.contacts, color), contactsPerItem / w.scratch.contacts.lanes);
    };
    // Colour by colour, the colour's joints and then its contacts (one constraint graph: they share
    // no moving body); then the constraints no colour took, one by one: joints (and revolute
    // trees), contacts, contact groups. Restitution has the contact stages only.
    auto rows = [&](RowPass pass) {
        const bool joints = pass != RowPass::Restitution;
        for (int color = 0; color < GraphColoring::overflow; ++color) {
            if (joints) add(Work::Joints, pass, color, jointUnitCount(w.scratch.joints, color), jointUnitsPerItem);
            addContactBlocks(Work::Contacts, pass, color);
        }
        if (joints) add(Work::SerialJoints, pass, 0, serialJointCount(w.scratch.joints) > 0 ? 1 : 0, 1);
        add(Work::SerialContacts, pass, 0, w.scratch.contacts.overflow.empty() ? 0 : 1, 1);
        add(Work::ContactGroups, pass, 0, w.scratch.contacts.groups.start.size() > 1 ? 1 : 0, 1);
    };
    for (int color = 0; color < GraphColoring::overflow; ++color) addContactBlocks(Work::LayOutContacts, RowPass::WarmStart, color);
    firstSubstepStage_ = stages_.size();
    add(Work::SubstepForces, RowPass::WarmStart, 0, bodies, bodiesPerItem);
    rows(RowPass::WarmStart);
    rows(RowPass::Solve);
    add(Work::IntegratePositions, RowPass::WarmStart, 0, bodies, bodiesPerItem);
    rows(RowPass::Relax);
    substepStages_ = stages_.size();
    rows(RowPass::Restitution);
    for (int color = 0; color < GraphColoring::overflow; ++color) addContactBlocks(Work::StoreContacts, RowPass::Restitution, color);
}

void SolverStages::execute(const SolverWorld& w, const StepContext& ctx, const SolverStage& stage, int begin, int end) const {
    using Work = SolverStage::Work;
    switch (stage.work) {
        case Work::LayOutContacts: layOutContactBlocks(w, ctx, stage.color, begin, end); break;
        case Work::SubstepForces: applySubstepForces(w.scratch.bodies, begin + 1, end + 1); break;
        case Work::Joints: jointRows(w.scratch.joints, w.scratch.bodies, ctx, stage.pass, stage.color, begin, end); break;
        case Work::SerialJoints: serialJointRows(w.scratch.joints, w.scratch.bodies, ctx, stage.pass); break;
        case Work::Contacts: contactRows(w.scratch.contacts, w.scratch.bodies, ctx, stage.pass, stage.color, begin, end); break;
        case Work::SerialContacts: serialContactRows(w.scratch.contacts, w.scratch.bodies, ctx, stage.pass); break;
        case Work::ContactGroups: contactGroupRows(w.scratch.contacts, w.scratch.bodies, w.scratch.joints, ctx, stage.pass); break;
        case Work::IntegratePositions: integratePositions(w.scratch.bodies, ctx, begin + 1, end + 1); break;
        case Work::StoreContacts: storeContactBlocks(w.scratch.contacts, w.contactCache, stage.color, begin, end); break;
    }
}

// One worker's walk through every stage of every substep, then the stages after them: claim items
// until none is left, then wait for the items other workers claimed.
void SolverStages::participate(const SolverWorld& w, const StepContext& ctx, int worker, int workerCount) {
    const size_t count = stages_.size();
    // Stage s in round `round` (a substep, or ctx.substeps for the stages after them), whose items
    // the round before left claimed `claimed` times.
    auto walk = [&](int round, size_t s, int claimed) {
        const SolverStage& stage = stages_[s];
        Sync& sync = sync_[static_cast<size_t>(round) * count + s];
        std::atomic<int>* claims = &claims_[static_cast<size_t>(firstClaim_[s])];
        const int items = stage.items();
        auto tryItem = [&](int item) {
            int expected = claimed;
            if (claims[item].load(std::memory_order_relaxed) != claimed ||
                !claims[item].compare_exchange_strong(expected, claimed + 1, std::memory_order_relaxed))
                return;
            const int begin = item * stage.unitsPerItem;
            execute(w, ctx, stage, begin, std::min(begin + stage.unitsPerItem, stage.units));
            sync.done.fetch_add(1, std::memory_order_release);
        };
        const int start = static_cast<int>(static_cast<int64_t>(items) * worker / workerCount);
        for (int item = start; item < items; ++item) tryItem(item);
        for (int item = start - 1; item >= 0; --item) tryItem(item);
        for (int spins = 0; sync.done.load(std::memory_order_acquire) < items; ++spins)
            if (spins > 100) std::this_thread::yield();
    };
    for (size_t s = 0; s < firstSubstepStage_; ++s) walk(ctx.substeps, s, 0);  // the extra round's syncs
    for (int substep = 0; substep < ctx.substeps; ++substep)
        for (size_t s = firstSubstepStage_; s < substepStages_; ++s) walk(substep, s, substep);
    for (size_t s = substepStages_; s < count; ++s) walk(ctx.substeps, s, 0);
}

void SolverStages::run(const SolverWorld& w, const StepContext& ctx) {
    if (w.workers.count() == 1) {
        for (size_t s = 0; s < firstSubstepStage_; ++s) execute(w, ctx, stages_[s], 0, stages_[s].units);
        for (int substep = 0; substep < ctx.substeps; ++substep)
            for (size_t s = firstSubstepStage_; s < substepStages_; ++s) execute(w, ctx, stages_[s], 0, stages_[s].units);
        for (size_t s = substepStages_; s < stages_.size(); ++s) execute(w, ctx, stages_[s], 0, stages_[s].units);
        return;
    }
    const size_t syncCount = stages_.size() * static_cast<size_t>(ctx.substeps + 1);  // a round more: the stages after the substeps
    if (syncCount > syncCapacity_) {  // grows with the colours in use, then stays
        syncCapacity_ = std::max(syncCount, 2 * syncCapacity_);
        sync_ = std::make_unique<Sync[]>(syncCapacity_);
    }
    for (size_t i = 0; i < syncCount; ++i) sync_[i].done.store(0, std::memory_order_relaxed);
    firstClaim_.resize(stages_.size());
    size_t claimCount = 0;
    for (size_t s = 0; s < stages_.size(); ++s) {
        firstClaim_[s] = static_cast<int>(claimCount);
        claimCount += static_cast<size_t>(stages_[s].items());
    }
    if (claimCount > claimCapacity_) {  // grows with the items in use, then stays
        claimCapacity_ = std::max(claimCount, 2 * claimCapacity_);
        claims_ = std::make_unique<std::atomic<int>[]>(claimCapacity_);
    }
    for (size_t i = 0; i < claimCount; ++i) claims_[i].store(0, std::memory_order_relaxed);
    const int workerCount = w.workers.count();
    w.workers.parallelFor(workerCount, 1, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) participate(w, ctx, k, workerCount);
    });
}

}  // namespace perpdot
