// The one block of the wide rows: N constraints of one graph colour (no two share a dynamic body)
// as the lanes of one row set. Contacts take it at four or eight lanes (ContactBlock,
// contact_solver_wide.hpp), the joints of one type at four (JointBlock, joint_store.hpp), and every
// pass runs over it with forBlocks (body_lanes.hpp).
#pragma once

#include <cstddef>

#include "core/solver/row_lanes.hpp"

namespace perpdot {

// What a pass reads comes first: the bodies' solver slots, the head (what the passes know of the
// block's lanes besides their rows: RowUses for contacts, the masses and type for joints), then
// the rows; the lanes' contact or joint indices, read by layout and store only, come last.
template <std::size_t N, std::size_t Floats, class Head>
struct alignas(64) LaneBlock {
    static constexpr int lanes = static_cast<int>(N);
    int bodyA[N] = {}, bodyB[N] = {};  // solver slots; an empty lane uses the static slot 0
    Head head;
    LaneRows<N, Floats> rows;
    int item[N] = {};  // each lane's contact (index in ContactCache::contacts) or joint (in JointStore::joints); -1: an empty lane
};

}  // namespace perpdot
