// A pool of items in one contiguous std::vector, addressed by index: destroyed slots go on a free
// list and the last one freed is reused first. Items carry `alive` and, when they are named by
// ids, a `generation` that destroy() advances, so an id of a destroyed item is recognised as stale.
//
// The free list's order decides which slot the next item takes, so snapshots save it as it is
// (snapshot.cpp) and restore it with restoreFreeList.
//
// Beside the items, a byte per slot says whether it is live: a pass over every slot (the
// narrowphase's over a contact pool of thousands of free slots) reads those bytes, not a cache
// line of each free item.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>


namespace perpdot {

template <class T>
class Pool {
public:
    static constexpr bool hasGeneration = requires(T item) { item.generation; };

    T& operator[](int index) { return items_[static_cast<size_t>(index)]; }
    const T& operator[](int index) const { return items_[static_cast<size_t>(index)]; }

    int capacity() const { return static_cast<int>(items_.size()); }  // slots, live or free
    bool isLive(int index) const { return live_[static_cast<size_t>(index)] != 0; }  // as items_[index].alive
    int size() const { return capacity() - static_cast<int>(free_.size()); }  // live items

    // Every slot, live or free, in index order.
    std::span<T> slots() { return items_; }
    std::span<const T> slots() const { return items_; }
    const std::vector<int>& freeList() const { return free_; }

    // fn(index, item) for each live item in index order.
    template <class Fn>
    void forEachLive(Fn fn) {
        forEachLiveIn(slots(), live_, fn);
    }
    template <class Fn>
    void forEachLive(Fn fn) const {
        forEachLiveIn(slots(), live_, fn);
    }

    bool isValid(int index, uint32_t generation) const
        requires hasGeneration
    {
        return index >= 0 && index < capacity() && items_[index].alive && items_[index].generation == generation;
    }

    // A value-initialised live item in the last freed slot, or in a new one; it keeps the slot's generation.
    int create() {
        int index;
        if (!free_.empty()) {
            index = free_.back();
            free_.pop_back();
        } else {
            index = capacity();
            items_.emplace_back();
            live_.push_back(0);
        }
        T& item = items_[index];
        if constexpr (hasGeneration) {
            const uint32_t generation = item.generation;
            item = T{};
            item.generation = generation;
        } else if constexpr (std::is_trivially_destructible_v<T>) {
            std::construct_at(&item);  // in the slot: `item = T{}` built a copy on the stack first
        } else {
            item = T{};
        }
        item.alive = true;
        live_[static_cast<size_t>(index)] = 1;
        return index;
    }

    // Frees the slot; the item keeps its data until the slot is reused.
    void destroy(int index) {
        T& item = items_[index];
        item.alive = false;
        live_[static_cast<size_t>(index)] = 0;
        if constexpr (hasGeneration) ++item.generation;
        free_.push_back(index);
    }

    // A snapshot's slots, all free and value-initialised until read into, then its free list
    // (checked by the reader against the live slots). An item that can reset itself keeping its
    // vectors' memory (resetKeepingMemory) does: reading into slots that held items allocates nothing.
    void restoreSlots(int count) {
        items_.resize(static_cast<size_t>(count));
        live_.assign(static_cast<size_t>(count), 0);
        for (T& item : items_) {
            if constexpr (requires { item.resetKeepingMemory(); }) item.resetKeepingMemory();
            else item = T{};
        }
        free_.clear();
    }
    // Takes over another pool's slots and free list (a discarded world's), whose memory
    // restoreSlots then reads into.
    void adoptStorage(Pool&& other) {
        items_ = std::move(other.items_);
        free_ = std::move(other.free_);
        live_ = std::move(other.live_);
    }
    // After the reader has set each slot's alive flag: they become the live bytes too.
    void restoreFreeList(std::vector<int> free) {
        for (size_t i = 0; i < items_.size(); ++i) live_[i] = items_[i].alive ? 1 : 0;
        free_ = std::move(free);
        free_.reserve(items_.size());  // room for every slot: destroying allocates nothing until the pool grows
    }

private:
    // Over copies of the spans, so that fn's writes (through a char, say) cannot make it reload the vectors.
    template <class Item, class Fn>
    static void forEachLiveIn(std::span<Item> items, std::span<const uint8_t> live, Fn& fn) {
        for (size_t i = 0; i < items.size(); ++i)
            if (live[i]) fn(static_cast<int>(i), items[i]);
    }

    std::vector<T> items_;
    std::vector<int> free_;
    std::vector<uint8_t> live_;  // by slot: 1 while live
};

}  // namespace perpdot
