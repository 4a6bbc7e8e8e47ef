// hmira/io/detail/vtk_impl.hpp
// The machinery of vtk.hpp shared by both encodings (cells into the soup, with every index and
// count checked), and the legacy .vtk reader and writer: a keyword line, then the data in
// ASCII tokens or big-endian binary, every declared count checked against the bytes left
// before anything is allocated.
#pragma once

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "../../core/result.hpp"
#include "json.hpp"
#include "polygon_soup.hpp"
#include "text_format.hpp"

namespace hmira::io::detail {

/// Cells as VTK keeps them: cell i is connectivity[offsets[i] .. offsets[i+1]).
struct vtk_cells {
    std::vector<std::uint64_t> offsets{0};
    std::vector<std::uint64_t> connectivity;
    std::size_t count() const { return offsets.size() - 1; }
};

/// Appends polygon cells (strip = false) or triangle strips (strip = true) to the soup. Errors
/// name the file, the section and the cell.
inline result<void> add_vtk_cells(polygon_soup& soup, const vtk_cells& cells, bool strip, const std::string& where) {
    const std::uint64_t n = soup.points.size();
    for (std::size_t c = 0; c < cells.count(); ++c) {
        const std::uint64_t b = cells.offsets[c], e = cells.offsets[c + 1];
        if (b > e || e > cells.connectivity.size())
            return fail(errc::parse_error,
                        where + ": cell " + std::to_string(c) + " has offsets out of order or range");
        if (e - b < 3)
            return fail(errc::parse_error, where + ": cell " + std::to_string(c) + " has " + std::to_string(e - b) +
                                               " points (a polygon or strip needs 3 or more)");
        for (auto k = b; k < e; ++k)
            if (cells.connectivity[k] >= n)
                return fail(errc::parse_error, where + ": cell " + std::to_string(c) + " names point " +
                                                   std::to_string(cells.connectivity[k]) + ", out of range [0, " +
                                                   std::to_string(n) + ")");
        if (!strip) {
            for (auto k = b; k < e; ++k) soup.indices.push_back(static_cast<std::uint32_t>(cells.connectivity[k]));
            soup.face_offsets.push_back(soup.indices.size());
            continue;
        }
        for (auto k = b; k + 2 < e; ++k) {
            const auto p = static_cast<std::uint32_t>(cells.connectivity[k]),
                       q = static_cast<std::uint32_t>(cells.connectivity[k + 1]),
                       r = static_cast<std::uint32_t>(cells.connectivity[k + 2]);
            if ((k - b) % 2 == 0)
                soup.indices.insert(soup.indices.end(), {p, q, r});
            else
                soup.indices.insert(soup.indices.end(), {q, p, r});
            soup.face_offsets.push_back(soup.indices.size());
        }
    }
    return {};
}

/// The legacy reader's position in the file: keyword lines, then ASCII tokens or binary data.
class vtk_legacy_cursor {
public:
    vtk_legacy_cursor(std::string_view data, std::string name) : data_(data), name_(std::move(name)) {}

    hmira::error bad(const std::string& what) const {
        return fail(errc::parse_error, name_ + ": byte offset " + std::to_string(pos_) + ": " + what,
                    static_cast<long long>(pos_));
    }
    bool at_end() {
        skip_spaces();
        return pos_ >= data_.size();
    }
    std::size_t left() const { return data_.size() - pos_; }
    /// The rest of the current line, whole (for the header's first three lines).
    std::string_view raw_line() {
        const std::size_t nl = data_.find('\n', pos_);
        std::string_view l = data_.substr(pos_, nl == std::string_view::npos ? std::string_view::npos : nl - pos_);
        pos_ = nl == std::string_view::npos ? data_.size() : nl + 1;
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        return l;
    }
    /// The next whitespace-separated token.
    std::string_view token() {
        skip_spaces();
        const std::size_t begin = pos_;
        while (pos_ < data_.size() && !is_space(data_[pos_])) ++pos_;
        return data_.substr(begin, pos_ - begin);
    }
    /// Past the end of the current line: where binary data starts after a keyword line.
    void end_line() {
        while (pos_ < data_.size() && data_[pos_] != '\n') ++pos_;
        if (pos_ < data_.size()) ++pos_;
    }
    result<std::uint64_t> count(const char* what) {
        const auto t = token();
        std::uint64_t v = 0;
        const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
        if (t.empty() || r.ec != std::errc() || r.ptr != t.data() + t.size())
            return bad(std::string(what) + ": '" + printable(std::string(t.substr(0, 32))) + "' is not a count");
        return v;
    }
    /// `n` numbers of a binary element of `size` bytes (big-endian), or ASCII tokens, as T.
    template <class T>
    result<void> values(bool binary, std::string_view type, std::uint64_t n, std::vector<T>& out, const char* what) {
        const std::size_t size = type_size(type);
        if (size == 0)
            return bad(std::string(what) + ": data type '" + printable(std::string(type.substr(0, 32))) +
                       "' is not read");
        // Every value takes `size` bytes, or 2 characters (digit and separator) in ASCII.
        if (n > (binary ? left() / size : (left() + 1) / 2))
            return bad(std::string(what) + ": " + std::to_string(n) + " values declared, more than the " +
                       std::to_string(left()) + " bytes left can hold");
        out.resize(static_cast<std::size_t>(n));
        if (!binary) {
            for (auto& v : out) {
                const auto t = token();
                double d = 0;
                if (!parse_double(t, d))
                    return bad(std::string(what) + ": '" + printable(std::string(t.substr(0, 32))) +
                               "' is not a number");
                if constexpr (std::is_integral_v<T>) {
                    if (!(d >= 0 && d < 1.8e19) || d != std::floor(d))
                        return bad(std::string(what) + ": " + number_text(d) + " is not a non-negative integer");
                }
                v = static_cast<T>(d);
            }
            return {};
        }
        end_line();
        if (n > left() / size) return bad(std::string(what) + ": binary data runs past the end of the file");
        const bool is_float =
            type == "float" || type == "double" || type == "vtktypefloat32" || type == "vtktypefloat64";
        const bool is_signed = !is_float && !type.starts_with("unsigned") && !type.starts_with("vtktypeuint");
        const char* p = data_.data() + pos_;
        for (std::size_t i = 0; i < out.size(); ++i, p += size) {
            std::uint64_t bits = 0;
            for (std::size_t k = 0; k < size; ++k) bits = bits << 8 | static_cast<unsigned char>(p[k]);
            double d;
            if (is_float && size == 4) {
                d = std::bit_cast<float>(static_cast<std::uint32_t>(bits));
            } else if (is_float) {
                d = std::bit_cast<double>(bits);
            } else if (is_signed) {
                const int shift = static_cast<int>(64 - 8 * size);
                const auto s = static_cast<std::int64_t>(bits << shift) >> shift;
                if constexpr (std::is_integral_v<T>) {
                    if (s < 0) {
                        pos_ = static_cast<std::size_t>(p - data_.data());
                        return bad(std::string(what) + ": value " + std::to_string(i) + " is negative");
                    }
                    out[i] = static_cast<T>(s);
                    continue;
                }
                d = static_cast<double>(s);
            } else {
                if constexpr (std::is_integral_v<T>) {
                    out[i] = static_cast<T>(bits);
                    continue;
                }
                d = static_cast<double>(bits);
            }
            out[i] = static_cast<T>(d);
        }
        pos_ += out.size() * size;
        return {};
    }

private:
    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
    void skip_spaces() {
        while (pos_ < data_.size() && is_space(data_[pos_])) ++pos_;
    }
    static std::size_t type_size(std::string_view t) {
        if (t == "char" || t == "unsigned_char" || t == "vtktypeint8" || t == "vtktypeuint8") return 1;
        if (t == "short" || t == "unsigned_short" || t == "vtktypeint16" || t == "vtktypeuint16") return 2;
        if (t == "int" || t == "unsigned_int" || t == "float" || t == "vtktypeint32" || t == "vtktypeuint32" ||
            t == "vtktypefloat32")
            return 4;
        if (t == "long" || t == "unsigned_long" || t == "double" || t == "vtkIdType" || t == "vtktypeint64" ||
            t == "vtktypeuint64" || t == "vtktypefloat64")
            return 8;
        return 0;
    }
    std::string_view data_;
    std::string name_;
    std::size_t pos_ = 0;
};

/// A cell section: "n size" then n runs of "count i0 i1 ..." (version < 5), or "n_offsets
/// n_connectivity" then OFFSETS and CONNECTIVITY arrays (version 5).
inline result<vtk_cells> read_legacy_cells(vtk_legacy_cursor& c, bool binary, bool v5, const char* what) {
    auto n = c.count(what);
    if (!n) return n.error();
    auto size = c.count(what);
    if (!size) return size.error();
    vtk_cells cells;
    if (v5) {
        for (int part = 0; part < 2; ++part) {
            const auto key = c.token();
            if (key != (part ? "CONNECTIVITY" : "OFFSETS"))
                return c.bad(std::string(what) + ": expected " + (part ? "CONNECTIVITY" : "OFFSETS"));
            const auto type = c.token();
            auto ok = c.values(binary, type, part ? *size : *n, part ? cells.connectivity : cells.offsets, what);
            if (!ok) return ok.error();
        }
        if (cells.offsets.empty()) cells.offsets.push_back(0);
        if (cells.offsets.front() != 0 || cells.offsets.back() != cells.connectivity.size())
            return c.bad(std::string(what) + ": OFFSETS do not span CONNECTIVITY");
        return cells;
    }
    std::vector<std::uint64_t> flat;
    auto ok = c.values(binary, "int", *size, flat, what);
    if (!ok) return ok.error();
    cells.offsets.reserve(static_cast<std::size_t>(std::min<std::uint64_t>(*n, flat.size())) + 1);
    cells.connectivity.reserve(flat.size());
    std::size_t at = 0;
    for (std::uint64_t i = 0; i < *n; ++i) {
        if (at >= flat.size() || flat[at] > flat.size() - at - 1)
            return c.bad(std::string(what) + ": cell " + std::to_string(i) + " runs past the " + std::to_string(*size) +
                         " values declared");
        const auto k = static_cast<std::size_t>(flat[at]);
        cells.connectivity.insert(cells.connectivity.end(), flat.begin() + static_cast<std::ptrdiff_t>(at + 1),
                                  flat.begin() + static_cast<std::ptrdiff_t>(at + 1 + k));
        cells.offsets.push_back(cells.connectivity.size());
        at += 1 + k;
    }
    return cells;
}

/// Parses a legacy .vtk file: POLYDATA (POLYGONS, TRIANGLE_STRIPS; VERTICES and LINES skipped)
/// or UNSTRUCTURED_GRID (triangles, quads, polygons and strips kept, other cells skipped). The
/// file's point and cell data are not read.
inline result<polygon_soup> parse_vtk_legacy(std::string_view data, const std::string& name) {
    vtk_legacy_cursor c(data, name);
    const auto first = c.raw_line();
    if (!first.starts_with("# vtk DataFile Version")) return c.bad("not a legacy VTK file (first line)");
    int major = 0;
    {
        const auto v = first.substr(22);
        const auto digits = v.find_first_not_of(' ');
        if (digits != std::string_view::npos) std::from_chars(v.data() + digits, v.data() + v.size(), major);
    }
    (void)c.raw_line();  // title
    const auto encoding = c.token();
    if (encoding != "ASCII" && encoding != "BINARY") return c.bad("expected ASCII or BINARY");
    const bool binary = encoding == "BINARY", v5 = major >= 5;
    if (c.token() != "DATASET") return c.bad("expected DATASET");
    const auto dataset = c.token();
    const bool grid = dataset == "UNSTRUCTURED_GRID";
    if (dataset != "POLYDATA" && !grid)
        return fail(errc::unsupported, name + ": DATASET " + printable(std::string(dataset.substr(0, 32))) +
                                           " (only POLYDATA and UNSTRUCTURED_GRID are read)");
    polygon_soup soup;
    bool have_points = false;
    vtk_cells grid_cells;
    std::vector<std::uint64_t> grid_types;
    while (!c.at_end()) {
        const auto key = c.token();
        if (key == "POINTS") {
            auto n = c.count("POINTS");
            if (!n) return n.error();
            const auto type = c.token();
            std::vector<double> xyz;
            if (*n > std::uint64_t{0xffffffffu}) return fail(errc::unsupported, name + ": 2^32 or more points");
            if (auto ok = c.values(binary, type, *n * 3, xyz, "POINTS"); !ok) return ok.error();
            soup.points.resize(static_cast<std::size_t>(*n));
            for (std::size_t i = 0; i < soup.points.size(); ++i) {
                soup.points[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
                if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) || !std::isfinite(xyz[3 * i + 2]))
                    return fail(errc::parse_error, name + ": POINTS: point " + std::to_string(i) + " is not finite");
            }
            have_points = true;
        } else if (key == "POLYGONS" || key == "TRIANGLE_STRIPS" || key == "VERTICES" || key == "LINES") {
            if (!have_points) return c.bad(std::string(key) + " before POINTS");
            const std::string what(key);
            auto cells = read_legacy_cells(c, binary, v5, what.c_str());
            if (!cells) return cells.error();
            if (key == "POLYGONS" || key == "TRIANGLE_STRIPS")
                if (auto ok = add_vtk_cells(soup, *cells, key == "TRIANGLE_STRIPS", name + ": " + what); !ok)
                    return ok.error();
        } else if (key == "CELLS" && grid) {
            if (!have_points) return c.bad("CELLS before POINTS");
            auto cells = read_legacy_cells(c, binary, v5, "CELLS");
            if (!cells) return cells.error();
            grid_cells = std::move(*cells);
        } else if (key == "CELL_TYPES" && grid) {
            auto n = c.count("CELL_TYPES");
            if (!n) return n.error();
            if (*n != grid_cells.count()) return c.bad("CELL_TYPES count differs from CELLS");
            if (auto ok = c.values(binary, "int", *n, grid_types, "CELL_TYPES"); !ok) return ok.error();
        } else if (key == "METADATA") {
            c.end_line();
            while (c.left() > 0 && !c.raw_line().empty()) {  // up to the blank line that ends it
            }
        } else if (key == "POINT_DATA" || key == "CELL_DATA" || key == "FIELD") {
            break;
        } else {
            return c.bad("unexpected '" + printable(std::string(key.substr(0, 32))) + "'");
        }
    }
    if (grid) {
        if (grid_types.size() != grid_cells.count()) return c.bad("CELLS without CELL_TYPES");
        vtk_cells polygons, strips;
        for (std::size_t i = 0; i < grid_cells.count(); ++i) {
            const auto t = grid_types[i];
            if (t != 5 && t != 6 && t != 7 && t != 9) continue;  // triangle, strip, polygon, quad
            auto& into = t == 6 ? strips : polygons;
            into.connectivity.insert(
                into.connectivity.end(),
                grid_cells.connectivity.begin() + static_cast<std::ptrdiff_t>(grid_cells.offsets[i]),
                grid_cells.connectivity.begin() + static_cast<std::ptrdiff_t>(grid_cells.offsets[i + 1]));
            into.offsets.push_back(into.connectivity.size());
        }
        if (auto ok = add_vtk_cells(soup, polygons, false, name + ": CELLS"); !ok) return ok.error();
        if (auto ok = add_vtk_cells(soup, strips, true, name + ": CELLS (strips)"); !ok) return ok.error();
    }
    return soup;
}

/// Big-endian bytes of a value, as legacy binary VTK stores it.
template <class V>
void append_big_endian(std::string& out, V v) {
    auto bits = std::bit_cast<std::conditional_t<sizeof(V) == 8, std::uint64_t, std::uint32_t>>(v);
    for (int k = static_cast<int>(sizeof(V)) - 1; k >= 0; --k) out += static_cast<char>((bits >> (8 * k)) & 0xff);
}

}  // namespace hmira::io::detail
