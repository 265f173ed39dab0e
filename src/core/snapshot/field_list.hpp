// Field lists: one description of a persisted struct, read by both the snapshot writer and its
// reader, so that the two cannot disagree. A struct T is persisted by declaring
//
//     constexpr auto fields(const T*) {
//         return std::tuple{field("a", &T::a), field("b", &T::b).anyBits(), field("c", &T::c).since(3)};
//     }
//
// next to the others (snapshot_fields.hpp; a joint type's in its joint_<type>.cpp). Members are written in list order as little-endian
// values (bool: one byte 0/1, float: its bits, Vec2: two floats, enums and ints: their width,
// structs with their own field list: recursively). Reading checks what it can alone: booleans are
// 0 or 1, floats are finite unless the field is marked anyBits(); cross-field checks (ranges,
// links) stay with the caller.
//
// Versions: a field added in format version N is marked .since(N); reading a snapshot of an older
// version leaves it at the struct's default. Format 1 stored joint type data as the struct's raw
// bytes; readLayoutV1 reads that layout back from the same list (declaration order, natural
// alignment), so the list must keep the members of format 1 in declaration order.
#pragma once

#include <cstdint>
#include <tuple>
#include <type_traits>

#include "core/snapshot/byte_io.hpp"

namespace perpdot {

template <class T, class M>
struct Field {
    const char* name;
    M T::*member;
    uint32_t addedIn = 1;   // format version that added the field
    bool finiteOnly = true;  // floats: refuse NaN and infinity on reading

    constexpr Field since(uint32_t version) const { return {name, member, version, finiteOnly}; }
    // Any float bits load (contact and joint values next to wild bodies may be non-finite, and
    // a world's own snapshot must always load back).
    constexpr Field anyBits() const { return {name, member, addedIn, false}; }
};

template <class T, class M>
constexpr Field<T, M> field(const char* name, M T::*member) {
    return {name, member};
}

// A struct whose layout changed must have its field list reviewed (then update the size there).
template <class T, size_t Size>
constexpr bool reviewedLayout = sizeof(void*) != 8 || sizeof(T) == Size;

template <class T>
concept Persisted = requires(const T* t) { fields(t); };

template <class T>
constexpr auto fieldsOf() {
    return fields(static_cast<const T*>(nullptr));
}

// --- one value ---

template <class V>
void writeValue(ByteWriter& out, const V& v) {
    if constexpr (std::is_same_v<V, bool>) out.boolean(v);
    else if constexpr (std::is_same_v<V, float>) out.f32(v);
    else if constexpr (std::is_same_v<V, Vec2>) out.vec2(v);
    else if constexpr (std::is_enum_v<V>) writeValue(out, static_cast<std::underlying_type_t<V>>(v));
    else if constexpr (std::is_integral_v<V>) {
        static_assert(sizeof(V) <= 4);
        if constexpr (sizeof(V) == 1) out.u8(static_cast<uint8_t>(v));
        else if constexpr (sizeof(V) == 2) out.u16(static_cast<uint16_t>(v));
        else out.u32(static_cast<uint32_t>(v));
    } else {
        static_assert(Persisted<V>, "a persisted member needs a field list of its own type");
        std::apply([&](const auto&... f) { (writeValue(out, v.*(f.member)), ...); }, fieldsOf<V>());
    }
}

// Flattened: a struct's read inlines every field's, so the tens of thousands of fields of a
// snapshot cost no call each (an 820-body restore: −17 % instructions).
template <class V>
[[gnu::flatten]] void readValue(ByteReader& in, V& v, bool finiteOnly, uint32_t version) {
    if constexpr (std::is_same_v<V, bool>) v = in.boolean();
    else if constexpr (std::is_same_v<V, float>) v = finiteOnly ? in.finite() : in.f32();
    else if constexpr (std::is_same_v<V, Vec2>) v = finiteOnly ? in.finiteVec2() : in.vec2();
    else if constexpr (std::is_enum_v<V>) {
        std::underlying_type_t<V> raw{};
        readValue(in, raw, finiteOnly, version);
        v = static_cast<V>(raw);  // the caller checks the range
    } else if constexpr (std::is_integral_v<V>) {
        if constexpr (sizeof(V) == 1) v = static_cast<V>(in.u8());
        else if constexpr (sizeof(V) == 2) v = static_cast<V>(in.u16());
        else v = static_cast<V>(in.u32());
    } else {
        std::apply([&](const auto&... f) { (readField(in, v, f, finiteOnly, version), ...); }, fieldsOf<V>());
    }
}

// A field of a struct inside an anyBits() field inherits anyBits.
template <class T, class M>
void readField(ByteReader& in, T& object, const Field<T, M>& f, bool finiteOnly, uint32_t version) {
    if (f.addedIn <= version) readValue(in, object.*(f.member), finiteOnly && f.finiteOnly, version);
}

// --- whole structs ---

template <Persisted T>
void writeFields(ByteWriter& out, const T& object) {
    writeValue(out, object);
}

// Reads the fields a snapshot of in.version holds; the others keep their values in `object`.
template <Persisted T>
void readFields(ByteReader& in, T& object) {
    readValue(in, object, true, in.version);
}

// Format 1's raw struct bytes, walked with the list: each member of format 1 at its natural
// alignment (padding bytes skipped), a struct padded to its own alignment.
template <class V>
void readLayoutV1(ByteReader& in, V& v, size_t& offset) {
    const auto align = [&] {
        const size_t pad = (alignof(V) - offset % alignof(V)) % alignof(V);
        in.skip(pad);
        offset += pad;
    };
    align();
    if constexpr (Persisted<V>) {
        std::apply([&](const auto&... f) { ((f.addedIn == 1 ? readLayoutV1(in, v.*(f.member), offset) : void()), ...); },
                   fieldsOf<V>());
        align();
    } else {
        readValue(in, v, false, 1);
        offset += sizeof(V);
    }
}

}  // namespace perpdot
