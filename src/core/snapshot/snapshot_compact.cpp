// Compact snapshots: the XOR of this world's snapshot bytes with a baseline snapshot, as runs of
// zero bytes (skipped) and literal bytes (kept). What did not change since the baseline — static
// geometry, sleeping islands, settings, joints' definitions — is a zero run; an awake body costs
// the bytes of its motion and of its contacts' warm-start impulses that changed. The snapshot is
// taken futureOnly (snapshot.cpp): contact values that the next narrowphase recomputes are zero,
// so they never differ.
//
// Layout: magic "PERPDOTC", the compact format version (u32), FNV-1a of the baseline (u64), the
// length of the full snapshot (u32), then pairs (zero run, literal run) until the length is
// covered. A pair starts with one header byte, the zero run's length in the high nibble and the
// literal run's in the low one; a nibble of 15 means 15 plus a LEB128 varint that follows (zero
// run's first). The literal run's XORed bytes come last.
#include <algorithm>
#include <cstring>
#include <memory>

#include "core/snapshot/snapshot.hpp"
#include "core/snapshot/snapshot_fields.hpp"
#include "core/world/handle_check.hpp"

namespace perpdot {

namespace {

constexpr uint8_t compactMagic[8] = {'P', 'E', 'R', 'P', 'D', 'O', 'T', 'C'};

// 4: (zero, literal) varint pairs, versioned with the full format. 5: nibble headers. 6: the
// baseline's hash in four streams. 7: contacts keep their mixed materials (before, zeros the
// narrowphase recomputed; it no longer does, so a version 6 snapshot would restore frictionless).
constexpr uint32_t compactFormatVersion = 8;
constexpr size_t nibbleEscape = 15;

uint64_t word(const uint8_t* bytes) {
    uint64_t w;
    std::memcpy(&w, bytes, sizeof w);
    return w;
}

// FNV-1a over 8-byte words in four interleaved streams (so that their multiplies overlap), folded
// together, then the tail: only tells baselines apart, so it may be fast.
uint64_t fnv1a(std::span<const uint8_t> bytes) {
    constexpr uint64_t prime = 0x100000001b3ull, basis = 0xcbf29ce484222325ull;
    uint64_t streams[4] = {basis, basis, basis, basis};
    size_t i = 0;
    for (; i + 32 <= bytes.size(); i += 32)
        for (size_t k = 0; k < 4; ++k) streams[k] = (streams[k] ^ word(&bytes[i + 8 * k])) * prime;
    uint64_t h = basis;
    for (uint64_t stream : streams) h = (h ^ stream) * prime;
    for (; i + 8 <= bytes.size(); i += 8) h = (h ^ word(&bytes[i])) * prime;
    for (; i < bytes.size(); ++i) h = (h ^ bytes[i]) * prime;
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

uint8_t nibble(size_t length) { return static_cast<uint8_t>(std::min(length, nibbleEscape)); }

size_t runLength(ByteReader& in, uint8_t nibble) { return nibble < nibbleEscape ? nibble : nibbleEscape + varint(in); }

// The baseline padded with zeros to the snapshot's length, read where both differ in size.
uint8_t baselineByte(std::span<const uint8_t> baseline, size_t i) { return i < baseline.size() ? baseline[i] : 0; }

// The end of the run of bytes equal to the baseline's from i, compared a word at a time.
size_t equalRunEnd(std::span<const uint8_t> full, std::span<const uint8_t> baseline, size_t i) {
    const size_t both = std::min(full.size(), baseline.size());
    while (i + 8 <= both && word(&full[i]) == word(&baseline[i])) i += 8;
    while (i < full.size() && full[i] == baselineByte(baseline, i)) ++i;
    return i;
}

}  // namespace

std::vector<uint8_t> World::baselineSnapshot() const {
    checkUnlocked(isLocked(), "baselineSnapshot");
    return writeSnapshot(*impl_, true);
}

std::vector<uint8_t> World::compactSnapshot(std::span<const uint8_t> baseline) const {
    checkUnlocked(isLocked(), "compactSnapshot");
    const std::vector<uint8_t> full = writeSnapshot(*impl_, true);
    ByteWriter out;
    for (uint8_t m : compactMagic) out.u8(m);
    out.u32(compactFormatVersion);
    out.u64(fnv1a(baseline));
    out.u32(static_cast<uint32_t>(full.size()));
    for (size_t i = 0; i < full.size();) {
        const size_t zeroStart = i;
        i = equalRunEnd(full, baseline, i);
        const size_t literalStart = i;
        // A literal run ends at the first equal byte: a new pair's header costs what the byte would.
        while (i < full.size() && full[i] != baselineByte(baseline, i)) ++i;
        const size_t zeros = literalStart - zeroStart, literal = i - literalStart;
        out.u8(static_cast<uint8_t>(nibble(zeros) << 4 | nibble(literal)));
        if (zeros >= nibbleEscape) varint(out, zeros - nibbleEscape);
        if (literal >= nibbleEscape) varint(out, literal - nibbleEscape);
        for (size_t k = literalStart; k < i; ++k) out.u8(full[k] ^ baselineByte(baseline, k));
    }
    return std::move(out.bytes);
}

void World::restoreCompact(std::span<const uint8_t> baseline, std::span<const uint8_t> compact) {
    checkUnlocked(isLocked(), "restoreCompact");
    ByteReader in(compact);
    for (uint8_t m : compactMagic)
        if (in.u8() != m) in.fail("not a perpdot compact snapshot (bad magic)");
    if (const uint32_t version = in.u32(); version != compactFormatVersion)
        in.fail("compact snapshot format version " + std::to_string(version) + " is not supported (this build reads " +
                std::to_string(compactFormatVersion) + "; take a new baseline and compact snapshots with this build)");
    if (in.u64() != fnv1a(baseline)) in.fail("the compact snapshot was taken against another baseline");
    const uint32_t size = in.u32();
    if (size > baseline.size() + 64 * compact.size()) in.fail("the compact snapshot's length is implausible");
    // Every byte is written once (no zero-filling first): a zero run is the baseline's bytes (zeros
    // past its end), a literal run its XORed bytes with the baseline's (as they are past its end).
    const auto full = std::make_unique_for_overwrite<uint8_t[]>(size);
    uint8_t* out = full.get();
    const auto inBaseline = [&](size_t i, size_t length) { return std::min(length, baseline.size() - std::min(baseline.size(), i)); };
    for (size_t i = 0; i < size;) {
        const uint8_t header = in.u8();
        const size_t zeros = runLength(in, header >> 4), literal = runLength(in, header & 0x0F);
        if (zeros > size - i || literal > size - i - zeros) in.fail("a run goes past the end");
        const size_t zerosInBaseline = inBaseline(i, zeros);
        if (zerosInBaseline > 0) std::memcpy(out + i, &baseline[i], zerosInBaseline);
        std::fill(out + i + zerosInBaseline, out + i + zeros, uint8_t{0});
        i += zeros;
        const std::span<const uint8_t> xored = in.bytes(literal);
        const size_t literalInBaseline = inBaseline(i, literal);
        for (size_t k = 0; k < literalInBaseline; ++k) out[i + k] = xored[k] ^ baseline[i + k];
        std::copy(xored.begin() + static_cast<std::ptrdiff_t>(literalInBaseline), xored.end(), out + i + literalInBaseline);
        i += literal;
    }
    in.expectEnd();
    restore(std::span<const uint8_t>(out, size));
}

}  // namespace perpdot
