#include "perpdot/state_hash.hpp"

#include <bit>

namespace perpdot {
namespace {

// FNV-1a, 64-bit: h = (h xor byte) * prime, byte by byte (little-endian order of each float's bits).
constexpr uint64_t fnvOffsetBasis = 14695981039346656037ull;
constexpr uint64_t fnvPrime = 1099511628211ull;

void mix(uint64_t& hash, float value) {
    const uint32_t bits = std::bit_cast<uint32_t>(value);
    for (int byte = 0; byte < 4; ++byte) {
        hash ^= (bits >> (8 * byte)) & 0xFFu;
        hash *= fnvPrime;
    }
}

}  // namespace

uint64_t stateHash(const World& world) {
    uint64_t hash = fnvOffsetBasis;
    for (BodyId body : world.bodies()) {
        const Vec2 p = world.position(body), v = world.linearVelocity(body);
        for (float value : {p.x, p.y, world.angle(body), v.x, v.y, world.angularVelocity(body)}) mix(hash, value);
    }
    return hash;
}

}  // namespace perpdot
