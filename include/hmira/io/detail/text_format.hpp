// hmira/io/detail/text_format.hpp
// Number parsing and printing for the text formats: std::from_chars / std::to_chars, so that
// numbers round-trip exactly and parsing does not depend on the C locale; and a cursor that
// walks the text once, counting lines for file:line messages.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/progress.hpp"

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

/// Shortest text that reads back as the same float.
inline void append_number(std::string& out, float v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

inline void append_number(std::string& out, std::uint64_t v) {
    char buf[24];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    out.append(buf, r.ptr);
}

inline void append_number(std::string& out, std::uint32_t v) { append_number(out, std::uint64_t{v}); }

/// Dense output numbering of the live vertices (index -> position in the file), so meshes
/// with deleted elements write compact files.
template <class M, class T>
std::vector<std::uint32_t> dense_vertex_numbers(const M& mesh) {
    std::vector<std::uint32_t> number(T::vertex_index_bound(mesh), UINT32_MAX);
    std::uint32_t k = 0;
    for (auto v : T::vertices(mesh)) number[T::vertex_index(mesh, v)] = k++;
    return number;
}

/// A forward cursor over text. Blanks are spaces, tabs and carriage returns; a newline ends
/// a line and is only crossed by next_line() (or skip_space_and_newlines()), which count lines.
class text_cursor {
public:
    explicit text_cursor(std::string_view text)
        : p_(text.data()), begin_(text.data()), end_(text.data() + text.size()) {}

    bool at_end() const noexcept { return p_ >= end_; }
    std::size_t line() const noexcept { return line_; }
    std::size_t offset() const noexcept { return static_cast<std::size_t>(p_ - begin_); }
    std::size_t size() const noexcept { return static_cast<std::size_t>(end_ - begin_); }
    const char* pos() const noexcept { return p_; }
    void set_pos(const char* p) noexcept { p_ = p; }

    void skip_blanks() noexcept {
        while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r')) ++p_;
    }
    /// True when only blanks remain on this line (or a comment starting with `comment`).
    bool at_line_end(char comment = '\0') noexcept {
        skip_blanks();
        return p_ >= end_ || *p_ == '\n' || (comment != '\0' && *p_ == comment);
    }
    /// Moves past the next newline (or to the end). Returns false at the end of the text.
    bool next_line() noexcept {
        if (p_ >= end_) return false;
        const void* nl = std::memchr(p_, '\n', static_cast<std::size_t>(end_ - p_));
        if (!nl) {
            p_ = end_;
            return false;
        }
        p_ = static_cast<const char*>(nl) + 1;
        ++line_;
        return true;
    }
    /// Skips blanks, newlines and comment lines (starting with `comment`).
    void skip_space_and_newlines(char comment = '\0') noexcept {
        for (;;) {
            skip_blanks();
            if (p_ >= end_) return;
            if (*p_ == '\n') {
                ++p_;
                ++line_;
            } else if (comment != '\0' && *p_ == comment) {
                next_line();
            } else {
                return;
            }
        }
    }
    /// The next token on this line (empty at the line's end).
    std::string_view token() noexcept {
        skip_blanks();
        const char* s = p_;
        while (p_ < end_ && *p_ != ' ' && *p_ != '\t' && *p_ != '\r' && *p_ != '\n') ++p_;
        return {s, static_cast<std::size_t>(p_ - s)};
    }
    /// Reads a number on this line that must be followed by a blank, a newline or the end.
    template <class N>
    bool number(N& out) noexcept {
        skip_blanks();
        const char* s = p_;
        if (s < end_ && *s == '+') ++s;
        const auto r = std::from_chars(s, end_, out);
        if (r.ec != std::errc() || r.ptr == s) return false;
        if (r.ptr < end_ && !is_delimiter(*r.ptr)) return false;
        p_ = r.ptr;
        return true;
    }
    /// The token at the cursor, for "'x' is not a number" messages (does not move).
    std::string_view peek_token() const noexcept {
        const char* s = p_;
        while (s < end_ && (*s == ' ' || *s == '\t' || *s == '\r')) ++s;
        const char* e = s;
        while (e < end_ && !is_delimiter(*e) && e - s < 40) ++e;
        return {s, static_cast<std::size_t>(e - s)};
    }

private:
    static bool is_delimiter(char c) noexcept { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }
    const char* p_;
    const char* begin_;
    const char* end_;
    std::size_t line_ = 1;
};

/// True when the three values of a point or vector are finite (no NaN, no infinity), as
/// coordinates and normals must be.
template <class V>
bool all_finite(const V& v) noexcept {
    return std::isfinite(static_cast<double>(v[0])) && std::isfinite(static_cast<double>(v[1])) &&
           std::isfinite(static_cast<double>(v[2]));
}

/// A colour channel from a file as a byte, or nothing when it is no colour: NaN, infinite,
/// or outside [0, 255] for byte channels (bytes = true) or [0, 1] for fractional ones.
inline std::optional<std::uint8_t> color_channel(double v, bool bytes) noexcept {
    if (bytes) {
        if (!(v >= 0 && v <= 255)) return std::nullopt;
        return static_cast<std::uint8_t>(v);
    }
    if (!(v >= 0 && v <= 1)) return std::nullopt;
    return static_cast<std::uint8_t>(v * 255.0 + 0.5);
}

/// The number for a message: shortest form, "nan"/"inf" as such.
inline std::string number_text(double v) {
    std::string s;
    append_number(s, v);
    return s;
}

/// "'abc' is not a number" / "missing number" for the token at the cursor.
inline std::string describe_bad_number(const text_cursor& c) {
    const auto tok = c.peek_token();
    if (tok.empty()) return "a number is missing (line ends early)";
    // Built by append: GCC 12 warns falsely (-Wrestrict) on "'" + std::string(...).
    std::string s;
    s.reserve(tok.size() + 20);
    s += '\'';
    s.append(tok);
    s += "' is not a number";
    return s;
}

/// A reader's progress: reports the share of the input parsed to a progress_function, through
/// a progress_gate, every `step` bytes at most; free when no function is set. tick() returns
/// false once the function has asked to stop, and the reader then returns cancelled().
class progress_ticker {
public:
    progress_ticker(const progress_function& report, std::uint64_t total)
        : gate_(report, static_cast<std::size_t>(total)), active_(static_cast<bool>(report)), total_(total) {}

    /// Records that the reader has reached byte `done`.
    [[nodiscard]] bool tick(std::uint64_t done) {
        if (!active_ || done < next_) return true;
        next_ = done + step;
        const bool go = gate_.advance(static_cast<std::size_t>(done > reported_ ? done - reported_ : 0));
        reported_ = std::max(reported_, done);
        return go;
    }
    /// Reports the whole input read.
    void finish() {
        if (active_ && reported_ < total_) (void)gate_.advance(static_cast<std::size_t>(total_ - reported_));
    }
    /// The error a reader returns when tick() said stop, at `where` (file and line or offset).
    static hmira::error cancelled(const std::string& where) {
        return fail(errc::cancelled, where + ": reading cancelled");
    }

private:
    static constexpr std::uint64_t step = 4u << 20;
    hmira::detail::progress_gate gate_;
    bool active_;
    std::uint64_t total_;
    std::uint64_t reported_ = 0;
    std::uint64_t next_ = 0;
};

}  // namespace hmira::io::detail
