// PairSet: linear probing with backward-shift deletion (pair_set.hpp).
#include "collide/pair_set.hpp"

#include <algorithm>
#include <bit>

namespace perpdot::collide {

// Fibonacci hashing: the top bits of key·2^64/φ spread consecutive proxy ids across the table.
size_t PairSet::home(uint64_t key) const { return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_); }

size_t PairSet::slotOf(uint64_t key) const {
    const size_t mask = slots_.size() - 1;
    size_t i = home(key);
    while (slots_[i] != key && slots_[i] != empty) i = (i + 1) & mask;
    return i;
}

bool PairSet::contains(uint64_t key) const { return count_ > 0 && slots_[slotOf(key)] == key; }

bool PairSet::insert(uint64_t key) {
    // At most half full, so probe runs stay short.
    if (2 * (count_ + 1) > slots_.size()) rehash(slots_.empty() ? 64 : 2 * slots_.size());
    const size_t i = slotOf(key);
    if (slots_[i] == key) return false;
    slots_[i] = key;
    ++count_;
    return true;
}

void PairSet::erase(uint64_t key) {
    if (count_ == 0) return;
    size_t hole = slotOf(key);
    if (slots_[hole] != key) return;
    // Close the hole: a later key of the run moves into it unless its home lies after the hole
    // (cyclically, in (hole, j]), where a lookup would not pass the hole to reach it.
    const size_t mask = slots_.size() - 1;
    for (size_t j = (hole + 1) & mask; slots_[j] != empty; j = (j + 1) & mask) {
        const size_t distanceToJ = (j - home(slots_[j])) & mask;
        const size_t distanceToHole = (j - hole) & mask;
        if (distanceToJ >= distanceToHole) {
            slots_[hole] = slots_[j];
            hole = j;
        }
    }
    slots_[hole] = empty;
    --count_;
}

void PairSet::reserve(size_t count) {
    if (2 * count > slots_.size()) rehash(std::bit_ceil(std::max<size_t>(64, 2 * count)));
}

void PairSet::rehash(size_t slotCount) {
    std::vector<uint64_t> old(slotCount, empty);
    old.swap(slots_);
    shift_ = 64 - std::countr_zero(slots_.size());
    count_ = 0;
    for (uint64_t key : old)
        if (key != empty) insert(key);
}

}  // namespace perpdot::collide
