// The set of broadphase pairs that have a contact, keyed by the two proxy ids packed into 64 bits
// (proxyPairKey). Open addressing in one flat array: linear probing from a multiplicative hash,
// deletion by shifting the probe run back (no tombstones). It grows to the peak pair count and
// then never allocates, however many pairs come and go.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace perpdot::collide {

class PairSet {
public:
    bool contains(uint64_t key) const;
    bool insert(uint64_t key);  // false if already present
    void erase(uint64_t key);   // no-op if absent
    // Starts loading the key's home slot: a caller that knows its next keys ahead hides the miss.
    void prefetch(uint64_t key) const {
        if (!slots_.empty()) __builtin_prefetch(&slots_[home(key)], 1);
    }
    size_t size() const { return count_; }
    void reserve(size_t count);  // room for `count` keys without growing (a restore's contacts)

private:
    static constexpr uint64_t empty = 0;  // proxyPairKey is never 0: its two ids differ
    size_t home(uint64_t key) const;
    size_t slotOf(uint64_t key) const;  // the key's slot, or the empty slot ending its probe run
    void rehash(size_t slotCount);  // a power of two

    std::vector<uint64_t> slots_;
    size_t count_ = 0;
    int shift_ = 64;  // 64 - log2(slot count)
};

}  // namespace perpdot::collide
