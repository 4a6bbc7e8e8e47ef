// hmira/core/enum_names.hpp
// The names of an option enum's values, written once beside the enum and shared by every
// front end: the CLI's choices, Python's string arguments and the messages that list them.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>

namespace hmira {

/// An enum E takes part by declaring, in its own namespace, a function found by argument-
/// dependent lookup that lists each value with its name:
///
///     constexpr auto enum_names(subdivision_scheme) {
///         return std::array{std::pair{subdivision_scheme::loop, std::string_view("loop")}, ...};
///     }
template <class E>
concept named_enum = std::is_enum_v<E> && requires { enum_names(E{}); };

/// The name of `value` ("" for a value the list lacks). O(number of values).
template <named_enum E>
constexpr std::string_view to_string(E value) {
    for (const auto& [v, name] : enum_names(E{}))
        if (v == value) return name;
    return {};
}

/// The value named `name`, or nothing. Names are matched exactly. O(number of values).
template <named_enum E>
constexpr std::optional<E> from_string(std::string_view name) {
    for (const auto& [v, n] : enum_names(E{}))
        if (n == name) return v;
    return std::nullopt;
}

/// Every name, quoted and separated by commas ("'loop', 'sqrt3', 'catmull-clark'"), for a
/// message that lists the choices.
template <named_enum E>
std::string quoted_names() {
    std::string out;
    for (const auto& [v, name] : enum_names(E{})) {
        (void)v;
        if (!out.empty()) out += ", ";
        // Appended piece by piece: GCC 12 at -O3 warns (-Wrestrict, wrongly) on "'" + string.
        out += '\'';
        out.append(name);
        out += '\'';
    }
    return out;
}

/// Every name, quoted, as a choice in prose ("'below' or 'above'", "'none', 'membrane' or
/// 'thin-plate'"), for a message that says what a value must be.
template <named_enum E>
std::string quoted_choices() {
    const auto& names = enum_names(E{});
    std::string out;
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (i > 0) out += i + 1 == names.size() ? " or " : ", ";
        out += '\'';
        out.append(names[i].second);
        out += '\'';
    }
    return out;
}

}  // namespace hmira
