// hmira/io/detail/vtp_impl.hpp
// The XML PolyData (.vtp) reader and writer of vtk.hpp. Arrays may be ascii, inline binary
// (base64) or appended (raw or base64), with a UInt32 or UInt64 size header, little- or
// big-endian, and zlib-compressed blocks when zlib is available. Every declared size is checked
// against the bytes the file has left (and a compressed array's total against the input limit)
// before anything is allocated.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "../../core/result.hpp"
#include "text_format.hpp"
#include "vtk_impl.hpp"
#include "xml.hpp"
#include "zip.hpp"

namespace hmira::io::detail {

/// A DataArray as the XML describes it; its bytes are decoded later.
struct vtp_array {
    std::string type, format, name;
    std::uint64_t components = 1, offset = 0;
    std::string_view text;
    bool present = false;
};

/// One Piece: its counts and the arrays hmira reads.
struct vtp_piece {
    std::uint64_t points = 0, polys = 0, strips = 0;
    vtp_array positions, poly_connectivity, poly_offsets, strip_connectivity, strip_offsets;
};

/// The file-wide settings of the VTKFile element and where the appended data starts.
struct vtp_file {
    std::string name;
    bool big_endian = false, compressed = false;
    std::size_t header_size = 4;
    std::string_view appended;  // after the '_'
    bool appended_base64 = false;
    std::uint64_t limit = 0;
    hmira::error bad(const std::string& what) const { return fail(errc::parse_error, name + ": " + what); }
};

inline std::size_t vtp_type_size(std::string_view t) {
    if (t == "Int8" || t == "UInt8") return 1;
    if (t == "Int16" || t == "UInt16") return 2;
    if (t == "Int32" || t == "UInt32" || t == "Float32") return 4;
    if (t == "Int64" || t == "UInt64" || t == "Float64") return 8;
    return 0;
}

/// Bytes from raw data or base64 text (quartet by quartet, so separately padded runs, as VTK
/// writes header and data, decode as one stream).
class vtp_source {
public:
    vtp_source(std::string_view data, bool base64) : data_(data), base64_(base64) {}
    /// An upper bound on the bytes still available.
    std::uint64_t bound() const {
        return base64_ ? (data_.size() - pos_) / 4 * 3 + buffered_.size() : data_.size() - pos_;
    }
    bool read(std::size_t n, std::string& out) {
        if (!base64_) {
            if (n > data_.size() - pos_) return false;
            out.append(data_.substr(pos_, n));
            pos_ += n;
            return true;
        }
        while (buffered_.size() < n) {
            char q[4];
            int got = 0;
            while (got < 4 && pos_ < data_.size()) {
                const char c = data_[pos_++];
                if (xml_reader::is_space(c)) continue;
                q[got++] = c;
            }
            if (got < 4) return false;
            int v[4], pad = 0;
            for (int k = 0; k < 4; ++k) {
                v[k] = digit(q[k]);
                if (q[k] == '=' && k >= 2) {
                    v[k] = 0, ++pad;
                } else if (v[k] < 0 || pad) {
                    return false;
                }
            }
            const std::uint32_t x =
                std::uint32_t(v[0]) << 18 | std::uint32_t(v[1]) << 12 | std::uint32_t(v[2]) << 6 | std::uint32_t(v[3]);
            buffered_ += static_cast<char>(x >> 16);
            if (pad < 2) buffered_ += static_cast<char>((x >> 8) & 0xff);
            if (pad < 1) buffered_ += static_cast<char>(x & 0xff);
        }
        out.append(buffered_, 0, n);
        buffered_.erase(0, n);
        return true;
    }

private:
    static int digit(char c) {
        if (c >= 'A' && c <= 'Z') return c - 'A';
        if (c >= 'a' && c <= 'z') return c - 'a' + 26;
        if (c >= '0' && c <= '9') return c - '0' + 52;
        if (c == '+') return 62;
        if (c == '/') return 63;
        return -1;
    }
    std::string_view data_;
    bool base64_;
    std::size_t pos_ = 0;
    std::string buffered_;
};

/// Reverses each `size`-byte element in place (big-endian files).
inline void swap_elements(std::string& bytes, std::size_t size) {
    if (size < 2) return;
    for (std::size_t i = 0; i + size <= bytes.size(); i += size)
        std::reverse(bytes.begin() + i, bytes.begin() + i + size);
}

/// The array's element bytes in native (little-endian) order, however the file stores them.
inline result<std::string> vtp_bytes(const vtp_file& f, const vtp_array& a, const std::string& where) {
    const std::size_t size = vtp_type_size(a.type);
    const bool appended = a.format == "appended";
    if (appended && a.offset > f.appended.size())
        return f.bad(where + ": offset " + std::to_string(a.offset) + " is past the appended data");
    vtp_source src(appended ? f.appended.substr(static_cast<std::size_t>(a.offset)) : a.text,
                   appended ? f.appended_base64 : true);
    const std::size_t hs = f.header_size;
    auto header = [&](std::size_t n, std::vector<std::uint64_t>& out) -> bool {
        std::string h;
        if (n > src.bound() / hs || !src.read(n * hs, h)) return false;
        if (f.big_endian) swap_elements(h, hs);
        out.resize(n);
        for (std::size_t i = 0; i < n; ++i) out[i] = hs == 8 ? le_u64(h.data() + 8 * i) : le_u32(h.data() + 4 * i);
        return true;
    };
    std::string out;
    std::vector<std::uint64_t> h;
    if (!f.compressed) {
        if (!header(1, h)) return f.bad(where + ": truncated size header");
        if (h[0] > src.bound())
            return f.bad(where + ": declares " + std::to_string(h[0]) + " bytes, more than the file has left");
        if (!src.read(static_cast<std::size_t>(h[0]), out)) return f.bad(where + ": truncated data");
    } else {
        if (!header(3, h)) return f.bad(where + ": truncated compression header");
        const std::uint64_t blocks = h[0], block = h[1], last = h[2] ? h[2] : h[1];
        std::vector<std::uint64_t> packed;
        if (!header(static_cast<std::size_t>(std::min<std::uint64_t>(blocks, src.bound())), packed) ||
            packed.size() != blocks)
            return f.bad(where + ": " + std::to_string(blocks) +
                         " compressed blocks declared, more than the file holds");
        const std::uint64_t total = blocks ? (blocks - 1) * block + last : 0;
        if (block > f.limit || (blocks && (blocks - 1) > f.limit / std::max<std::uint64_t>(block, 1)) ||
            total > f.limit)
            return f.bad(where + ": declares more uncompressed bytes than the input limit of " +
                         std::to_string(f.limit) + " (refused)");
        for (std::uint64_t b = 0; b < blocks; ++b) {
            std::string chunk;
            if (packed[b] > src.bound() || !src.read(static_cast<std::size_t>(packed[b]), chunk))
                return f.bad(where + ": compressed block " + std::to_string(b) + " runs past the end of the data");
            const std::uint64_t plain_size = b + 1 == blocks ? last : block;
            if (plain_size > deflate_bound(packed[b]))
                return f.bad(where + ": compressed block " + std::to_string(b) + " declares " +
                             std::to_string(plain_size) + " bytes, more than its data can inflate to");
            auto plain =
                inflate_exactly(chunk, plain_size, false, f.name + ": " + where + " block " + std::to_string(b));
            if (!plain) return plain.error();
            out += *plain;
        }
    }
    if (f.big_endian) swap_elements(out, size);
    return out;
}

/// The array's `n` values converted to T (checked: integers non-negative and whole, the count
/// exact).
template <class T>
result<void> vtp_values(const vtp_file& f, const vtp_array& a, std::uint64_t n, std::vector<T>& out,
                        const std::string& where) {
    const std::size_t size = vtp_type_size(a.type);
    if (size == 0)
        return fail(errc::unsupported, f.name + ": " + where + " has type '" + printable(a.type.substr(0, 32)) + "'");
    if (a.format == "ascii") {
        if (n > (a.text.size() + 1) / 2)
            return f.bad(where + ": " + std::to_string(n) + " values declared, more than the text holds");
        out.resize(static_cast<std::size_t>(n));
        std::size_t pos = 0, i = 0;
        for (; i < out.size(); ++i) {
            while (pos < a.text.size() && xml_reader::is_space(a.text[pos])) ++pos;
            const std::size_t begin = pos;
            while (pos < a.text.size() && !xml_reader::is_space(a.text[pos])) ++pos;
            double d = 0;
            if (!parse_double(a.text.substr(begin, pos - begin), d))
                return f.bad(where + ": value " + std::to_string(i) + " is not a number");
            if constexpr (std::is_integral_v<T>)
                if (!(d >= 0 && d < 1.8e19) || d != std::floor(d))
                    return f.bad(where + ": value " + std::to_string(i) + " is not a non-negative integer");
            out[i] = static_cast<T>(d);
        }
        return {};
    }
    if (a.format != "binary" && a.format != "appended")
        return f.bad(where + ": format '" + printable(a.format.substr(0, 32)) + "' (ascii, binary or appended)");
    auto bytes = vtp_bytes(f, a, where);
    if (!bytes) return bytes.error();
    if (bytes->size() / size != n || bytes->size() % size)
        return f.bad(where + ": holds " + std::to_string(bytes->size()) + " bytes, not the " + std::to_string(n) +
                     " values of " + std::to_string(size) + " bytes its piece declares");
    out.resize(static_cast<std::size_t>(n));
    const char* p = bytes->data();
    const std::string_view t = a.type;
    // One loop per element type, chosen once (this is the bulk of reading a binary .vtp).
    auto convert = [&]<class S>(S) -> result<void> {
        for (std::size_t i = 0; i < out.size(); ++i) {
            S x;
            std::memcpy(&x, p + i * sizeof(S), sizeof(S));  // little-endian host
            if constexpr (std::is_integral_v<T> && std::is_floating_point_v<S>) {
                if (!(x >= 0 && x < S(1.8e19)) || x != std::floor(x))
                    return f.bad(where + ": value " + std::to_string(i) + " is not a non-negative integer");
            } else if constexpr (std::is_integral_v<T> && std::is_signed_v<S>) {
                if (x < 0) return f.bad(where + ": value " + std::to_string(i) + " is negative");
            }
            out[i] = static_cast<T>(x);
        }
        return {};
    };
    if (t == "Float32") return convert(float{});
    if (t == "Float64") return convert(double{});
    if (t == "Int8") return convert(std::int8_t{});
    if (t == "UInt8") return convert(std::uint8_t{});
    if (t == "Int16") return convert(std::int16_t{});
    if (t == "UInt16") return convert(std::uint16_t{});
    if (t == "Int32") return convert(std::int32_t{});
    if (t == "UInt32") return convert(std::uint32_t{});
    if (t == "Int64") return convert(std::int64_t{});
    return convert(std::uint64_t{});
}

inline result<std::uint64_t> vtp_count(const xml_reader& x, const char* key) {
    const auto* v = x.find(key);
    if (!v) return std::uint64_t{0};
    std::uint64_t n = 0;
    const auto r = std::from_chars(v->data(), v->data() + v->size(), n);
    if (r.ec != std::errc() || r.ptr != v->data() + v->size())
        return x.bad(std::string(key) + "=\"" + printable(std::string(v->substr(0, 32))) + "\" is not a count");
    return n;
}

/// The cells of one section (Polys or Strips) of a piece.
inline result<vtk_cells> vtp_cells(const vtp_file& f, const vtp_array& connectivity, const vtp_array& offsets,
                                   std::uint64_t n, const std::string& where) {
    vtk_cells cells;
    if (n == 0) return cells;
    if (!connectivity.present || !offsets.present) return f.bad(where + " lacks its connectivity or offsets array");
    std::vector<std::uint64_t> ends;
    if (auto ok = vtp_values(f, offsets, n, ends, where + " offsets"); !ok) return ok.error();
    const std::uint64_t total = ends.back();
    for (std::size_t i = 0; i < ends.size(); ++i)
        if (ends[i] < (i ? ends[i - 1] : 0))
            return f.bad(where + " offsets: cell " + std::to_string(i) + " ends before it starts");
    if (auto ok = vtp_values(f, connectivity, total, cells.connectivity, where + " connectivity"); !ok)
        return ok.error();
    cells.offsets.reserve(ends.size() + 1);
    cells.offsets.insert(cells.offsets.end(), ends.begin(), ends.end());
    return cells;
}

/// Parses a .vtp file: every piece's points, polygons and triangle strips (vertices and lines
/// skipped), point and cell data not read. `limit` bounds a compressed array's inflated size.
inline result<polygon_soup> parse_vtp(std::string_view data, const std::string& name, std::uint64_t limit) {
    xml_reader x(data, name, 64);
    vtp_file f;
    f.name = name;
    f.limit = limit;
    std::vector<vtp_piece> pieces;
    std::string section;  // the element whose DataArrays are being read
    vtp_array* current = nullptr;
    bool root = false;
    for (;;) {
        auto e = x.next();
        if (!e) return e.error();
        if (*e == xml_event::done) break;
        if (*e == xml_event::text) {
            if (current && current->text.empty()) current->text = x.text;
            continue;
        }
        if (*e == xml_event::end) {
            if (x.name == "DataArray") current = nullptr;
            if (x.name == "Points" || x.name == "Polys" || x.name == "Strips") section.clear();
            continue;
        }
        const std::string_view tag = x.name;
        if (!root) {
            if (tag != "VTKFile") return x.bad("the root element is not <VTKFile>");
            root = true;
            const auto* type = x.find("type");
            if (!type || *type != "PolyData")
                return fail(errc::unsupported, name + ": VTKFile type is not PolyData (only .vtp is read)");
            if (const auto* b = x.find("byte_order")) f.big_endian = *b == "BigEndian";
            if (const auto* h = x.find("header_type")) {
                if (*h != "UInt32" && *h != "UInt64") return x.bad("header_type must be UInt32 or UInt64");
                f.header_size = *h == "UInt64" ? 8 : 4;
            }
            if (const auto* c = x.find("compressor"); c && !c->empty()) {
                if (*c != "vtkZLibDataCompressor")
                    return fail(errc::unsupported, name + ": compressor " + printable(std::string(c->substr(0, 40))) +
                                                       " (only zlib is read)");
                f.compressed = true;
            }
        } else if (tag == "Piece") {
            current = nullptr;  // it points into the pieces, which may move
            vtp_piece p;
            auto n = vtp_count(x, "NumberOfPoints"), polys = vtp_count(x, "NumberOfPolys"),
                 strips = vtp_count(x, "NumberOfStrips");
            if (!n || !polys || !strips) return !n ? n.error() : !polys ? polys.error() : strips.error();
            p.points = *n, p.polys = *polys, p.strips = *strips;
            pieces.push_back(p);
        } else if (tag == "Points" || tag == "Polys" || tag == "Strips") {
            section = tag;
        } else if (tag == "PointData" || tag == "CellData" || tag == "Verts" || tag == "Lines" || tag == "FieldData") {
            if (!x.self_closing)
                if (auto ok = x.skip_element(); !ok) return ok.error();
        } else if (tag == "DataArray" && !pieces.empty() && !section.empty()) {
            vtp_array a;
            a.present = true;
            if (const auto* v = x.find("type")) a.type = *v;
            if (const auto* v = x.find("format")) a.format = *v;
            if (const auto* v = x.find("Name")) a.name = *v;
            auto components = vtp_count(x, "NumberOfComponents"), offset = vtp_count(x, "offset");
            if (!components || !offset) return !components ? components.error() : offset.error();
            a.components = *components ? *components : 1;
            a.offset = *offset;
            auto& p = pieces.back();
            vtp_array* slot = nullptr;
            if (section == "Points")
                slot = &p.positions;
            else if (a.name == "connectivity")
                slot = section == "Polys" ? &p.poly_connectivity : &p.strip_connectivity;
            else if (a.name == "offsets")
                slot = section == "Polys" ? &p.poly_offsets : &p.strip_offsets;
            if (slot && !slot->present) {
                *slot = a;
                current = x.self_closing ? nullptr : slot;
            }
        } else if (tag == "AppendedData") {
            const auto* enc = x.find("encoding");
            f.appended_base64 = !enc || *enc == "base64";
            std::size_t at = x.offset();
            while (at < data.size() && xml_reader::is_space(data[at])) ++at;
            if (at >= data.size() || data[at] != '_') return x.bad("<AppendedData> does not start with '_'", at);
            f.appended = data.substr(at + 1);
            break;  // what follows is not XML
        }
    }
    if (!root) return fail(errc::parse_error, name + ": no <VTKFile> element");
    polygon_soup soup;
    for (std::size_t k = 0; k < pieces.size(); ++k) {
        const auto& p = pieces[k];
        const std::string where = "Piece " + std::to_string(k);
        const std::size_t base = soup.points.size();
        if (p.points > std::uint64_t{0xffffffffu} - base)
            return fail(errc::unsupported, name + ": 2^32 or more points");
        if (p.points) {
            if (!p.positions.present) return f.bad(where + " has no Points array");
            if (p.positions.components != 3) return f.bad(where + " Points do not have 3 components");
            std::vector<double> xyz;
            if (auto ok = vtp_values(f, p.positions, p.points * 3, xyz, where + " Points"); !ok) return ok.error();
            for (std::size_t i = 0; i < p.points; ++i) {
                if (!std::isfinite(xyz[3 * i]) || !std::isfinite(xyz[3 * i + 1]) || !std::isfinite(xyz[3 * i + 2]))
                    return f.bad(where + " Points: point " + std::to_string(i) + " is not finite");
                soup.points.push_back({xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]});
            }
        }
        for (int strips = 0; strips < 2; ++strips) {
            const std::string what = where + (strips ? " Strips" : " Polys");
            auto cells = strips ? vtp_cells(f, p.strip_connectivity, p.strip_offsets, p.strips, what)
                                : vtp_cells(f, p.poly_connectivity, p.poly_offsets, p.polys, what);
            if (!cells) return cells.error();
            // Indices are relative to the piece: check against its points, then shift.
            for (auto& v : cells->connectivity)
                if (v >= p.points)
                    return f.bad(what + ": point " + std::to_string(v) + " out of range [0, " +
                                 std::to_string(p.points) + ")");
            for (auto& v : cells->connectivity) v += base;
            if (auto ok = add_vtk_cells(soup, *cells, strips == 1, name + ": " + what); !ok) return ok.error();
        }
    }
    return soup;
}

}  // namespace hmira::io::detail
