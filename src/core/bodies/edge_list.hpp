// Each body's list of the items that join it to another body (contacts, joints): intrusive and
// doubly linked through the items' `Edge edges[2]`, side 0 in bodyA's list and side 1 in bodyB's.
// An edge is named by its key, item*2 + side. A new edge goes to the front of its body's list, and
// lists are walked from the front: that order decides who is visited first (islands, sleep), so
// snapshots save each list as its keys, front first.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace perpdot {

struct Edge {
    int prev = -1, next = -1;  // edge keys in the body's list
};

class EdgeList {
public:
    // The first edge key of the body's list, -1 if it is empty.
    int head(int body) const { return static_cast<size_t>(body) < heads_.size() ? heads_[body] : -1; }

    // The edge after `key` in its body's list, -1 at the end.
    template <class Items>
    static int next(const Items& items, int key) {
        return items[key >> 1].edges[key & 1].next;
    }

    // fn(item, side) for each edge of the body's list, front first; fn may unlink the edge it is given.
    template <class Items, class Fn>
    void forEach(const Items& items, int body, Fn fn) const {
        for (int key = head(body); key >= 0;) {
            const int after = next(items, key);
            fn(key >> 1, key & 1);
            key = after;
        }
    }

    template <class Items>
    void link(Items& items, int item, int side, int body) {
        const int key = 2 * item + side;
        if (static_cast<size_t>(body) >= heads_.size()) heads_.resize(body + 1, -1);
        int& first = heads_[body];
        Edge& e = items[item].edges[side];
        e.prev = -1;
        e.next = first;
        if (first >= 0) items[first >> 1].edges[first & 1].prev = key;
        first = key;
    }

    template <class Items>
    void unlink(Items& items, int item, int side, int body) {
        Edge& e = items[item].edges[side];
        if (e.prev >= 0) items[e.prev >> 1].edges[e.prev & 1].next = e.next;
        else heads_[body] = e.next;
        if (e.next >= 0) items[e.next >> 1].edges[e.next & 1].prev = e.prev;
        e = {};
    }

    // The body's list as its edge keys, front first (for snapshots), and the list made from them.
    template <class Items>
    std::vector<int> keys(const Items& items, int body) const {
        std::vector<int> out;
        for (int key = head(body); key >= 0; key = next(items, key)) out.push_back(key);
        return out;
    }
    template <class Items>
    void restore(Items& items, int body, std::span<const int> keys) {
        for (auto key = keys.rbegin(); key != keys.rend(); ++key) link(items, *key >> 1, *key & 1, body);
    }

private:
    std::vector<int> heads_;  // by body index
};

}  // namespace perpdot
