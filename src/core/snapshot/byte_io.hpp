// Little-endian bytes for snapshots: a writer, and a bounds-checked reader that throws
// perpdot::Error on truncation or on a value outside its allowed range, never reading past the end.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "perpdot/error.hpp"
#include "perpdot/math.hpp"

namespace perpdot {

class ByteWriter {
public:
    void u8(uint8_t v) { bytes.push_back(v); }
    void u16(uint16_t v) { unsigned_<2>(v); }
    void u32(uint32_t v) { unsigned_<4>(v); }
    void u64(uint64_t v) { unsigned_<8>(v); }
    void i32(int32_t v) { u32(static_cast<uint32_t>(v)); }
    void boolean(bool v) { u8(v ? 1 : 0); }
    void f32(float v) { u32(std::bit_cast<uint32_t>(v)); }
    void vec2(Vec2 v) { f32(v.x); f32(v.y); }

    std::vector<uint8_t> bytes;

private:
    // A fixed size, so that the compiler turns the byte loop into one store.
    template <size_t Size>
    void unsigned_(uint64_t v) {
        const size_t at = bytes.size();
        bytes.resize(at + Size);
        for (size_t i = 0; i < Size; ++i) bytes[at + i] = static_cast<uint8_t>(v >> (8 * i));
    }
};

class ByteReader {
public:
    explicit ByteReader(std::span<const uint8_t> bytes) : bytes_(bytes) {}

    uint32_t version = 0;  // the format version of what is read, once its header is

    [[gnu::always_inline]] uint8_t u8() { return static_cast<uint8_t>(unsigned_<1>()); }
    uint16_t u16() { return static_cast<uint16_t>(unsigned_<2>()); }
    [[gnu::always_inline]] uint32_t u32() { return static_cast<uint32_t>(unsigned_<4>()); }
    uint64_t u64() { return unsigned_<8>(); }
    int32_t i32() { return static_cast<int32_t>(u32()); }
    bool boolean() {
        const uint8_t v = u8();
        if (v > 1) [[unlikely]] notBoolean(v);
        return v == 1;
    }
    // Any bits, NaN and infinity included, for contact and joint values: a world's own snapshot
    // must always load back, and its contacts may hold non-finite values next to wild bodies.
    [[gnu::always_inline]] float f32() { return std::bit_cast<float>(u32()); }
    // Body state, settings and broadphase boxes must be finite (the step keeps them so, and
    // Box2D's time of impact asserts on NaN).
    [[gnu::always_inline]] float finite() {
        const float v = f32();
        if (!std::isfinite(v)) [[unlikely]] notFinite();
        return v;
    }
    [[gnu::always_inline]] Vec2 finiteVec2() {
        const float x = finite();
        return {x, finite()};
    }
    [[gnu::always_inline]] Vec2 vec2() {
        const float x = f32();
        return {x, f32()};
    }
    // An int in [lo, hi].
    int integer(int lo, int hi, const char* what) {
        const int32_t v = i32();
        if (v < lo || v > hi)
            fail(std::string(what) + " " + std::to_string(v) + " is outside [" + std::to_string(lo) + ", " +
                 std::to_string(hi) + "]");
        return v;
    }
    // An element count, bounded by what the remaining bytes could hold (minBytes per element), so a
    // corrupt count cannot make the reader allocate gigabytes.
    int count(size_t minBytes, const char* what) {
        const uint32_t n = u32();
        if (n > 0x7FFFFFFFu || n * static_cast<uint64_t>(minBytes) > bytes_.size() - pos_)
            fail(std::string(what) + " count " + std::to_string(n) + " exceeds the remaining data");
        return static_cast<int>(n);
    }
    // The next `size` bytes as they are.
    std::span<const uint8_t> bytes(size_t size) {
        if (bytes_.size() - pos_ < size) truncated();
        pos_ += size;
        return bytes_.subspan(pos_ - size, size);
    }
    void skip(size_t size) { bytes(size); }
    void expectEnd() const {
        if (pos_ != bytes_.size()) fail(std::to_string(bytes_.size() - pos_) + " bytes left over after the end");
    }
    [[noreturn]] void fail(const std::string& why) const {
        throw Error("snapshot: " + why + " (at byte " + std::to_string(pos_) + ")");
    }

private:
    [[noreturn, gnu::cold, gnu::noinline]] void truncated() const { fail("truncated"); }
    [[noreturn, gnu::cold, gnu::noinline]] void notBoolean(uint8_t v) const { fail("a boolean is " + std::to_string(v)); }
    [[noreturn, gnu::cold, gnu::noinline]] void notFinite() const { fail("a number is not finite"); }

    // A fixed size, so that the compiler turns the byte loop into one load; the failure is out of
    // line, so that each read inlines to a compare and a load.
    template <size_t Size>
    [[gnu::always_inline]] uint64_t unsigned_() {
        if (bytes_.size() - pos_ < Size) [[unlikely]] truncated();
        uint64_t v = 0;
        for (size_t i = 0; i < Size; ++i) v |= static_cast<uint64_t>(bytes_[pos_ + i]) << (8 * i);
        pos_ += Size;
        return v;
    }

    std::span<const uint8_t> bytes_;
    size_t pos_ = 0;
};

}  // namespace perpdot
