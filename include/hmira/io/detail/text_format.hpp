// hmira/io/detail/text_format.hpp
// Number parsing and printing for the text formats: std::from_chars / std::to_chars, so that
// numbers round-trip exactly and parsing does not depend on the C locale.
#pragma once

#include <charconv>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "../../concepts.hpp"

namespace hmira::io::detail {

inline bool parse_double(std::string_view s, double& out) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

inline bool parse_long(std::string_view s, long long& out) {
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

/// Shortest text that reads back as the same double.
inline void append_number(std::string& out, double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

inline void append_number(std::string& out, std::uint64_t v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

/// Dense output numbering of the live vertices (index -> position in the file), so meshes
/// with deleted elements write compact files.
template <class M, class T>
std::vector<std::uint32_t> dense_vertex_numbers(const M& mesh) {
    std::vector<std::uint32_t> number(T::vertex_index_bound(mesh), UINT32_MAX);
    std::uint32_t k = 0;
    for (auto v : T::vertices(mesh)) number[T::vertex_index(mesh, v)] = k++;
    return number;
}

}  // namespace hmira::io::detail
