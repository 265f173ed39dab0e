// Compact snapshots: the XOR of this world's snapshot bytes with a baseline snapshot, as runs of
// zero bytes (skipped) and literal bytes (kept). What did not change since the baseline — static
// geometry, sleeping islands, settings, joints' definitions — is a zero run; an awake body costs
// the bytes of its motion and of its contacts' warm-start impulses that changed. The snapshot is
// taken futureOnly (snapshot.cpp): contact values that the next narrowphase recomputes are zero,
// so they never differ.
//
// Layout: magic "PERPDOTC", the format version (u32), FNV-1a of the baseline (u64), the length of
// the full snapshot (u32), then pairs (zero run, literal run) as LEB128 varints, each literal run
// followed by its XORed bytes, until the length is covered.
#include <algorithm>

#include "core/snapshot.hpp"
#include "core/snapshot_fields.hpp"

namespace perpdot {

namespace {

constexpr uint8_t compactMagic[8] = {'P', 'E', 'R', 'P', 'D', 'O', 'T', 'C'};

uint64_t fnv1a(std::span<const uint8_t> bytes) {
    uint64_t h = 0xcbf29ce484222325ull;
    for (uint8_t b : bytes) h = (h ^ b) * 0x100000001b3ull;
    return h;
}

void varint(ByteWriter& out, size_t v) {
    for (; v >= 0x80; v >>= 7) out.u8(static_cast<uint8_t>(v | 0x80));
    out.u8(static_cast<uint8_t>(v));
}

size_t varint(ByteReader& in) {
    size_t v = 0;
    for (int shift = 0; shift < 35; shift += 7) {
        const uint8_t b = in.u8();
        v |= static_cast<size_t>(b & 0x7F) << shift;
        if (!(b & 0x80)) return v;
    }
    in.fail("a run length is too long");
}

uint8_t baselineByte(std::span<const uint8_t> baseline, size_t i) { return i < baseline.size() ? baseline[i] : 0; }

}  // namespace

std::vector<uint8_t> World::baselineSnapshot() const {
    impl_->checkUnlocked("baselineSnapshot");
    return writeSnapshot(*impl_, true);
}

std::vector<uint8_t> World::compactSnapshot(std::span<const uint8_t> baseline) const {
    impl_->checkUnlocked("compactSnapshot");
    const std::vector<uint8_t> full = writeSnapshot(*impl_, true);
    ByteWriter out;
    for (uint8_t m : compactMagic) out.u8(m);
    out.u32(formatVersion);
    out.u64(fnv1a(baseline));
    out.u32(static_cast<uint32_t>(full.size()));
    for (size_t i = 0; i < full.size();) {
        const size_t zeroStart = i;
        while (i < full.size() && full[i] == baselineByte(baseline, i)) ++i;
        const size_t literalStart = i;
        // A literal run ends at two equal bytes in a row (one is cheaper to keep than a new run).
        while (i < full.size() && !(full[i] == baselineByte(baseline, i) &&
                                    (i + 1 == full.size() || full[i + 1] == baselineByte(baseline, i + 1))))
            ++i;
        varint(out, literalStart - zeroStart);
        varint(out, i - literalStart);
        for (size_t k = literalStart; k < i; ++k) out.u8(full[k] ^ baselineByte(baseline, k));
    }
    return std::move(out.bytes);
}

void World::restoreCompact(std::span<const uint8_t> baseline, std::span<const uint8_t> compact) {
    impl_->checkUnlocked("restoreCompact");
    ByteReader in(compact);
    for (uint8_t m : compactMagic)
        if (in.u8() != m) in.fail("not a perpdot compact snapshot (bad magic)");
    if (const uint32_t version = in.u32(); version != formatVersion)
        in.fail("compact snapshot format version " + std::to_string(version) + " is not " + std::to_string(formatVersion));
    if (in.u64() != fnv1a(baseline)) in.fail("the compact snapshot was taken against another baseline");
    const uint32_t size = in.u32();
    if (size > baseline.size() + 64 * compact.size()) in.fail("the compact snapshot's length is implausible");
    std::vector<uint8_t> full(size);
    for (size_t i = 0; i < full.size();) {
        const size_t zeros = varint(in), literal = varint(in);
        if (zeros > full.size() - i || literal > full.size() - i - zeros) in.fail("a run goes past the end");
        for (size_t end = i + zeros; i < end; ++i) full[i] = baselineByte(baseline, i);
        for (size_t end = i + literal; i < end; ++i) full[i] = in.u8() ^ baselineByte(baseline, i);
    }
    in.expectEnd();
    restore(full);
}

}  // namespace perpdot
