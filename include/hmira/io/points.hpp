// hmira/io/points.hpp
// Point lists as text: .xyz (x y [z] per line) and .csv (x,y[,z], an optional header line),
// what `hmira delaunay` triangulates. Parsed in one pass with file:line messages.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "../core/result.hpp"
#include "../core/vec3.hpp"
#include "detail/files.hpp"

namespace hmira::io {

/// Options of read_points_text().
struct points_text_options {
    /// CSV: the first line may be a header (it is skipped when it is not numbers).
    bool csv = false;
    /// Largest input read from a non-regular file (pipe, device, FIFO) before giving up with
    /// an error naming the file and the limit, as read_options::max_input_bytes.
    std::uint64_t max_input_bytes = detail::default_max_input_bytes;
};

/// Parses points, one per line: x y [z] separated by blanks, commas or semicolons; '#' starts
/// a comment; blank lines are skipped; columns after the third are ignored; z is 0 when
/// absent. With `csv`, a first line that is not numbers is a header.
/// Errors: parse_error naming `name:line` for a line with one number or a non-number, and for
/// a coordinate that is NaN or infinite. Complexity: O(bytes).
inline result<std::vector<vec3<double>>> parse_points_text(std::string_view text, const std::string& name,
                                                           bool csv = false) {
    std::vector<vec3<double>> pts;
    detail::line_reader lines(text);
    std::string_view line;
    while (lines.next(line)) {
        if (auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        double v[3] = {0, 0, 0};
        int n = 0;
        const char* p = line.data();
        const char* end = p + line.size();
        bool bad = false;
        while (p < end) {
            while (p < end && (*p == ' ' || *p == '\t' || *p == ',' || *p == ';')) ++p;
            if (p >= end) break;
            if (n == 3) break;  // extra columns are ignored
            const char* s = (*p == '+') ? p + 1 : p;
            auto r = std::from_chars(s, end, v[n]);
            if (r.ec != std::errc() || r.ptr == s) {
                bad = true;
                break;
            }
            p = r.ptr;
            ++n;
        }
        if (bad && csv && lines.line_number() == 1 && pts.empty()) continue;  // a header
        const auto where = [&] { return name + ":" + std::to_string(lines.line_number()); };
        if (bad || (n > 0 && n < 2))
            return fail(errc::parse_error,
                        where() + ": expected 'x y [z]', found '" + std::string(line.substr(0, 60)) + "'");
        if (n < 2) continue;
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
            return fail(errc::parse_error,
                        where() + ": point " + std::to_string(pts.size()) +
                            " has a coordinate that is not finite (NaN or infinity)",
                        static_cast<long long>(pts.size()));
        pts.push_back({v[0], v[1], v[2]});
    }
    return pts;
}

/// Reads a .xyz or .csv point file (see parse_points_text). Errors: io_error when the file
/// cannot be read (or a non-regular file passes options.max_input_bytes); the parse errors.
inline result<std::vector<vec3<double>>> read_points_text(const std::filesystem::path& path,
                                                          const points_text_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    return parse_points_text(file->text(), path.string(), options.csv);
}

}  // namespace hmira::io
