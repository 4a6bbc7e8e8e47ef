// hmira/io/detail/ply_types.hpp
// The value types of PLY properties (char ... double, under their old and sized names) and
// their byte-order handling, which the reader and the writer share.
#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>
#include <type_traits>

namespace hmira::io::detail {

enum class ply_type : std::uint8_t { invalid, i8, u8, i16, u16, i32, u32, f32, f64 };

inline ply_type ply_type_from(std::string_view s) {
    if (s == "char" || s == "int8") return ply_type::i8;
    if (s == "uchar" || s == "uint8") return ply_type::u8;
    if (s == "short" || s == "int16") return ply_type::i16;
    if (s == "ushort" || s == "uint16") return ply_type::u16;
    if (s == "int" || s == "int32") return ply_type::i32;
    if (s == "uint" || s == "uint32") return ply_type::u32;
    if (s == "float" || s == "float32") return ply_type::f32;
    if (s == "double" || s == "float64") return ply_type::f64;
    return ply_type::invalid;
}

inline std::size_t ply_size(ply_type t) {
    switch (t) {
        case ply_type::i8:
        case ply_type::u8: return 1;
        case ply_type::i16:
        case ply_type::u16: return 2;
        case ply_type::i32:
        case ply_type::u32:
        case ply_type::f32: return 4;
        case ply_type::f64: return 8;
        default: return 0;
    }
}

inline bool ply_is_integer(ply_type t) { return t != ply_type::f32 && t != ply_type::f64; }

template <class U>
U ply_swap(U v) {
    if constexpr (sizeof(U) == 2)
        return static_cast<U>(__builtin_bswap16(static_cast<std::uint16_t>(v)));
    else if constexpr (sizeof(U) == 4)
        return static_cast<U>(__builtin_bswap32(static_cast<std::uint32_t>(v)));
    else if constexpr (sizeof(U) == 8)
        return static_cast<U>(__builtin_bswap64(static_cast<std::uint64_t>(v)));
    else
        return v;
}

template <class V, bool Swap>
V ply_raw(const char* p) {
    if constexpr (sizeof(V) == 1) {
        V v;
        std::memcpy(&v, p, 1);
        return v;
    } else {
        using U = std::conditional_t<sizeof(V) == 2, std::uint16_t,
                                     std::conditional_t<sizeof(V) == 4, std::uint32_t, std::uint64_t>>;
        U u;
        std::memcpy(&u, p, sizeof u);
        if constexpr (Swap) u = ply_swap(u);
        V v;
        std::memcpy(&v, &u, sizeof v);
        return v;
    }
}

}  // namespace hmira::io::detail
