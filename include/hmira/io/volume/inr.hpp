// hmira/io/volume/inr.hpp
// INRIMAGE-4 volumes (.inr, and .inr.gz when zlib is available), the format of CGAL's sample
// volumes such as skull_2.9.inr and liver.inr.gz: a 256-byte text header, then the samples.
#pragma once

#include <bit>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "../../core/result.hpp"
#include "../../grids/dense_grid.hpp"
#include "../../grids/voxel_grid.hpp"
#include "../detail/files.hpp"
#include "raw.hpp"

// .inr.gz needs zlib: found by __has_include, so a program including this header links zlib
// (ZLIB::ZLIB) unless it defines HMIRA_NO_ZLIB, which turns .gz reading into an error.
#if __has_include(<zlib.h>) && !defined(HMIRA_NO_ZLIB)
#include <zlib.h>
#define HMIRA_HAS_ZLIB 1
#endif

namespace hmira::io {

namespace detail {

// The whole file, inflated when it is gzip-compressed (magic 1f 8b).
inline result<std::string> read_maybe_gzip(const std::filesystem::path& path) {
    auto raw = read_file(path);
    if (!raw) return raw.error();
    if (raw->size() < 2 || static_cast<unsigned char>((*raw)[0]) != 0x1f || static_cast<unsigned char>((*raw)[1]) != 0x8b)
        return raw;
#if defined(HMIRA_HAS_ZLIB)
    gzFile f = gzopen(path.string().c_str(), "rb");
    if (!f) return fail(errc::io_error, path.string() + ": cannot open the gzip stream");
    std::string out;
    std::vector<char> buf(1 << 20);
    while (true) {
        const int n = gzread(f, buf.data(), static_cast<unsigned>(buf.size()));
        if (n < 0) {
            int code = 0;
            const std::string msg = gzerror(f, &code);
            gzclose(f);
            return fail(errc::parse_error, path.string() + ": corrupt gzip data: " + msg);
        }
        if (n == 0) break;
        out.append(buf.data(), static_cast<std::size_t>(n));
    }
    // gzread stops quietly at a truncated stream; gzclose_r reports it.
    if (gzclose(f) != Z_OK) return fail(errc::parse_error, path.string() + ": truncated gzip data");
    return out;
#else
    return fail(errc::unsupported, path.string() + ": gzip-compressed, but hmira was built without zlib");
#endif
}

}  // namespace detail

/// What an INRIMAGE header says, for callers that want more than the samples.
struct inr_header {
    grid_geometry geometry;  ///< dimensions, origin (TX/TY/TZ) and spacing (VX/VY/VZ)
    std::string type;       ///< "float", "unsigned fixed" or "signed fixed"
    unsigned bits = 0;      ///< bits per sample: 8, 16, 32 or 64
    bool big_endian = false;       ///< CPU=sun or sgi
    std::size_t header_bytes = 0;  ///< offset of the first sample (a multiple of 256)
};

/// Parses the header of INRIMAGE text `bytes`. Errors: parse_error naming the problem.
inline result<inr_header> parse_inr_header(std::string_view bytes, const std::string& name) {
    constexpr std::string_view magic = "#INRIMAGE-4#{";
    if (bytes.substr(0, magic.size()) != magic)
        return fail(errc::parse_error, name + ": not an INRIMAGE-4 file (no '#INRIMAGE-4#{' header)");
    const auto end = bytes.find("##}");
    if (end == std::string_view::npos) return fail(errc::parse_error, name + ": header has no '##}' terminator (truncated?)");
    inr_header h;
    h.header_bytes = (end + 3 + 1 + 255) / 256 * 256;  // the header is padded to 256-byte blocks
    if (h.header_bytes > bytes.size()) return fail(errc::parse_error, name + ": file ends inside the header");
    long long dims[3] = {-1, -1, -1}, vdim = 1;
    double vox[3] = {1, 1, 1}, origin[3] = {0, 0, 0};
    std::string cpu = "decm";
    io::detail::line_reader lines(bytes.substr(magic.size(), end - magic.size()));
    std::string_view line;
    while (lines.next(line)) {
        const auto eq = line.find('=');
        if (eq == std::string_view::npos) continue;
        const std::string key(line.substr(0, eq));
        const std::string val(line.substr(eq + 1));
        auto number = [&](double& out) -> bool {
            try {
                std::size_t used = 0;
                out = std::stod(val, &used);
                return used > 0;
            } catch (...) {
                return false;
            }
        };
        double d = 0;
        auto bad = [&] { return fail(errc::parse_error, name + ": bad header value " + key + "=" + val); };
        if (key == "XDIM" || key == "YDIM" || key == "ZDIM" || key == "VDIM") {
            if (!number(d) || d < 0 || d != static_cast<double>(static_cast<long long>(d))) return bad();
            (key == "VDIM" ? vdim : dims[key[0] - 'X']) = static_cast<long long>(d);
        } else if (key == "VX" || key == "VY" || key == "VZ") {
            if (!number(d)) return bad();
            vox[key[1] - 'X'] = d;
        } else if (key == "TX" || key == "TY" || key == "TZ") {
            if (!number(d)) return bad();
            origin[key[1] - 'X'] = d;
        } else if (key == "TYPE") {
            h.type = val;
        } else if (key == "PIXSIZE") {
            if (!number(d)) return bad();
            h.bits = static_cast<unsigned>(d);
        } else if (key == "CPU") {
            cpu = val;
        }
    }
    for (int a = 0; a < 3; ++a)
        if (dims[a] < 0) return fail(errc::parse_error, name + ": header lacks " + std::string(1, char('X' + a)) + "DIM");
    if (vdim != 1) return fail(errc::unsupported, name + ": VDIM=" + std::to_string(vdim) + ", only scalar volumes (VDIM=1) are supported");
    if (h.type != "float" && h.type != "unsigned fixed" && h.type != "signed fixed")
        return fail(errc::unsupported, name + ": sample TYPE '" + h.type + "' is not float, unsigned fixed or signed fixed");
    const bool ok_bits = h.type == "float" ? (h.bits == 32 || h.bits == 64) : (h.bits == 8 || h.bits == 16 || h.bits == 32);
    if (!ok_bits) return fail(errc::unsupported, name + ": PIXSIZE=" + std::to_string(h.bits) + " bits is not supported for TYPE " + h.type);
    h.big_endian = cpu == "sun" || cpu == "sgi";
    h.geometry = {{std::size_t(dims[0]), std::size_t(dims[1]), std::size_t(dims[2])}, {origin[0], origin[1], origin[2]}, {vox[0], vox[1], vox[2]}};
    if (auto ok = check_grid_geometry(h.geometry, name); !ok) return ok.error();
    return h;
}

/// Reads an INRIMAGE-4 volume (optionally gzip-compressed) into float samples, whatever the
/// stored type (8/16/32-bit integers, 32/64-bit floats). Spacing from VX/VY/VZ, origin from
/// TX/TY/TZ when present.
/// Errors: io_error (cannot read); parse_error for a missing magic or terminator, missing or
/// bad dimensions, a file shorter than the header promises ("truncated"), or NaN samples;
/// unsupported for vector volumes (VDIM > 1), other sample types, or .gz without zlib;
/// invalid_argument for zero dimensions or spacing. O(N).
inline result<dense_grid<float>> read_inr(const std::filesystem::path& path) {
    const std::string name = path.string();
    auto bytes = detail::read_maybe_gzip(path);
    if (!bytes) return bytes.error();
    auto h = parse_inr_header(*bytes, name);
    if (!h) return h.error();
    const std::size_t n = h->geometry.size(), sample_bytes = h->bits / 8;
    const std::size_t have = bytes->size() - h->header_bytes;
    if (have < n * sample_bytes)
        return fail(errc::parse_error, name + ": truncated: the header promises " + std::to_string(n * sample_bytes) +
                                           " bytes of samples, the file holds " + std::to_string(have));
    const char* data = bytes->data() + h->header_bytes;
    const bool swap = sample_bytes > 1 && (h->big_endian != (std::endian::native == std::endian::big));
    auto convert = [&](auto tag) -> result<dense_grid<float>> {
        using V = decltype(tag);
        auto g = detail::samples_to_grid<V>(data, h->geometry, swap, name);
        if (!g) return g.error();
        if constexpr (std::is_same_v<V, float>) {
            return std::move(*g);
        } else {
            dense_grid<float> out(h->geometry);
            for (std::size_t q = 0; q < n; ++q) out.data()[q] = static_cast<float>(g->data()[q]);
            return out;
        }
    };
    if (h->type == "float") return h->bits == 32 ? convert(float{}) : convert(double{});
    const bool sign = h->type == "signed fixed";
    switch (h->bits) {
        case 8: return sign ? convert(std::int8_t{}) : convert(std::uint8_t{});
        case 16: return sign ? convert(std::int16_t{}) : convert(std::uint16_t{});
        default: return sign ? convert(std::int32_t{}) : convert(std::uint32_t{});
    }
}

}  // namespace hmira::io
