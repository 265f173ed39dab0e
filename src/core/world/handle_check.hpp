// The checks every call that takes a handle makes (Id, ids.hpp): not null, issued by this World,
// and naming a live slot of the generation it was issued for. The Error names the World call that
// was given the handle, "World::setTransform: stale BodyId {index 3, generation 2}": the accessors
// take the caller's name as a default argument, __builtin_FUNCTION() (GCC and Clang), so World's
// calls pass nothing, and nothing is built unless the check fails.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

#include "core/base/pool.hpp"
#include "perpdot/error.hpp"
#include "perpdot/ids.hpp"

namespace perpdot {

// A fresh World identity (never 0: the identity of no World).
inline uint32_t newWorldIdentity() {
    static std::atomic<uint32_t> last{0};
    uint32_t id = ++last;
    while (id == 0) id = ++last;  // after 2^32 Worlds
    return id;
}

// Which handles a World accepts (ids.hpp): those of the identity it issues handles with, which a
// restore takes from the snapshot (the snapshotted World's), and those of the identity it was
// made with.
struct WorldIdentity {
    uint32_t issued = newWorldIdentity();
    uint32_t own = issued;
    bool accepts(uint32_t world) const { return world == issued || world == own; }
};

// Whether `id` names a live item of `pool` in the World of identity `world`.
template <class T, class Tag>
bool isLiveHandle(const Pool<T>& pool, Id<Tag> id, const WorldIdentity& world) {
    return world.accepts(id.world) && pool.isValid(id.index, id.generation);
}

// The live item `id` names; `kind` ("BodyId") and `call` (the World call, "setTransform") name
// them in the Error.
template <class T, class Tag>
const T& checkedItem(const Pool<T>& pool, Id<Tag> id, const WorldIdentity& world, const char* kind, const char* call) {
    if (isLiveHandle(pool, id, world)) return pool[id.index];
    const std::string handle = std::string(kind) + " {index " + std::to_string(id.index) + ", generation " +
                               std::to_string(id.generation) + "}";
    std::string problem;
    if (id.isNull()) problem = "null " + handle;
    else if (!world.accepts(id.world)) problem = handle + " from another World";
    else problem = "stale " + handle;
    throw Error(std::string("World::") + call + ": " + problem);
}

// The handle of `pool`'s live item at `index`, as the World of identity `world` issues it.
template <class Handle, class T>
Handle handleAt(const Pool<T>& pool, int index, const WorldIdentity& world) {
    return {index, pool[index].generation, world.issued};
}

// World's calls that change it throw while it steps (its callbacks run inside step()).
inline void checkUnlocked(bool locked, const char* what) {
    if (locked) throw Error(std::string(what) + ": the world cannot be changed during step()");
}

}  // namespace perpdot
