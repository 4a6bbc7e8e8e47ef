// hmira/io/volume/inr.hpp
// INRIMAGE-4 volumes (.inr, and .inr.gz when zlib is available), the format of CGAL's sample
// volumes such as skull_2.9.inr and liver.inr.gz: a 256-byte text header, then the samples.
#pragma once

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
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

/// Options of read_inr().
struct inr_options {
    /// Largest input read from a non-regular file (pipe, device, FIFO) before giving up with
    /// an error naming the file and the limit; a regular file is read up to its size. The
    /// same limit as read_options::max_input_bytes. (Inflating .inr.gz is bounded by the
    /// header instead: see read_inr.)
    std::uint64_t max_input_bytes = detail::default_max_input_bytes;
};

/// What an INRIMAGE header says, for callers that want more than the samples.
struct inr_header {
    grid_geometry geometry;        ///< dimensions, origin (TX/TY/TZ) and spacing (VX/VY/VZ)
    std::string type;              ///< "float", "unsigned fixed" or "signed fixed"
    unsigned bits = 0;             ///< bits per sample: 8, 16, 32 or 64
    bool big_endian = false;       ///< CPU=sun or sgi
    std::size_t header_bytes = 0;  ///< offset of the first sample (a multiple of 256)
    /// Bytes of samples the header declares: dims x (bits / 8).
    std::uint64_t sample_bytes() const noexcept { return std::uint64_t{geometry.size()} * (bits / 8); }
};

/// Parses the header of INRIMAGE text `bytes` (the header alone, or more). Errors:
/// parse_error naming the problem and the key (a dimension that is not a whole number >= 1,
/// a spacing not finite and positive, an origin not finite, a grid too large); unsupported
/// for vector volumes and sample types or sizes other than those read_inr reads.
inline result<inr_header> parse_inr_header(std::string_view bytes, const std::string& name) {
    constexpr std::string_view magic = "#INRIMAGE-4#{";
    if (bytes.substr(0, magic.size()) != magic)
        return fail(errc::parse_error, name + ": not an INRIMAGE-4 file (no '#INRIMAGE-4#{' header)");
    const auto end = bytes.find("##}");
    if (end == std::string_view::npos)
        return fail(errc::parse_error, name + ": header has no '##}' terminator (truncated?)");
    inr_header h;
    h.header_bytes = (end + 3 + 1 + 255) / 256 * 256;  // the header is padded to 256-byte blocks
    if (h.header_bytes > bytes.size()) return fail(errc::parse_error, name + ": file ends inside the header");
    std::uint64_t dims[3] = {0, 0, 0}, vdim = 1;
    bool have_dim[3] = {false, false, false};
    double vox[3] = {1, 1, 1}, origin[3] = {0, 0, 0};
    std::string cpu = "decm";
    io::detail::line_reader lines(bytes.substr(magic.size(), end - magic.size()));
    std::string_view line;
    while (lines.next(line)) {
        const auto eq = line.find('=');
        if (eq == std::string_view::npos) continue;
        const std::string key(line.substr(0, eq));
        const std::string val(line.substr(eq + 1));
        // The leading number of the value ("PIXSIZE=8 bits" carries a unit after it).
        auto number = [&](double& out) -> bool {
            std::string_view v(val);
            while (!v.empty() && (v.front() == ' ' || v.front() == '\t')) v.remove_prefix(1);
            if (!v.empty() && v.front() == '+') v.remove_prefix(1);
            const auto r = std::from_chars(v.data(), v.data() + v.size(), out);
            return r.ec == std::errc() && r.ptr != v.data();
        };
        double d = 0;
        const std::string where =
            name + ": header line " + std::to_string(lines.line_number() + 1) + ": " + key + "=" + val.substr(0, 40);
        auto bad = [&](const char* why) { return fail(errc::parse_error, where + ": " + why); };
        if (key == "XDIM" || key == "YDIM" || key == "ZDIM" || key == "VDIM") {
            // 2^40 bounds every real volume and keeps the products below 2^64.
            if (!number(d) || !(d >= 1 && d <= 0x1p40) || d != std::floor(d))
                return bad("a dimension must be a whole number from 1 to 2^40");
            if (key == "VDIM") {
                vdim = static_cast<std::uint64_t>(d);
            } else {
                dims[key[0] - 'X'] = static_cast<std::uint64_t>(d);
                have_dim[key[0] - 'X'] = true;
            }
        } else if (key == "VX" || key == "VY" || key == "VZ") {
            if (!number(d) || !std::isfinite(d) || !(d > 0))
                return bad("a voxel size (spacing) must be a finite positive number");
            vox[key[1] - 'X'] = d;
        } else if (key == "TX" || key == "TY" || key == "TZ") {
            if (!number(d) || !std::isfinite(d)) return bad("an origin must be a finite number");
            origin[key[1] - 'X'] = d;
        } else if (key == "TYPE") {
            h.type = val;
        } else if (key == "PIXSIZE") {
            if (!number(d) || (d != 8 && d != 16 && d != 32 && d != 64))
                return bad("PIXSIZE must be 8, 16, 32 or 64 bits");
            h.bits = static_cast<unsigned>(d);
        } else if (key == "CPU") {
            cpu = val;
        }
    }
    for (int a = 0; a < 3; ++a)
        if (!have_dim[a])
            return fail(errc::parse_error, name + ": header lacks " + std::string(1, char('X' + a)) + "DIM");
    if (vdim != 1)
        return fail(errc::unsupported,
                    name + ": VDIM=" + std::to_string(vdim) + ", only scalar volumes (VDIM=1) are supported");
    if (h.type != "float" && h.type != "unsigned fixed" && h.type != "signed fixed")
        return fail(errc::unsupported,
                    name + ": sample TYPE '" + h.type.substr(0, 40) + "' is not float, unsigned fixed or signed fixed");
    const bool ok_bits =
        h.type == "float" ? (h.bits == 32 || h.bits == 64) : (h.bits == 8 || h.bits == 16 || h.bits == 32);
    if (!ok_bits)
        return fail(errc::unsupported,
                    name + ": PIXSIZE=" + std::to_string(h.bits) + " bits is not supported for TYPE " + h.type);
    h.big_endian = cpu == "sun" || cpu == "sgi";
    h.geometry = {{std::size_t(dims[0]), std::size_t(dims[1]), std::size_t(dims[2])},
                  {origin[0], origin[1], origin[2]},
                  {vox[0], vox[1], vox[2]}};
    // What is left for check_grid_geometry is the size: a problem of the file, so parse_error.
    if (auto ok = check_grid_geometry(h.geometry, name); !ok) return fail(errc::parse_error, ok.error().message);
    return h;
}

namespace detail {

inline bool is_gzip(std::string_view bytes) {
    return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
           static_cast<unsigned char>(bytes[1]) == 0x8b;
}

#if defined(HMIRA_HAS_ZLIB)
/// Inflates gzip data held in memory, a bounded amount at a time, so that a reader can look
/// at the header before deciding how much more to inflate. Concatenated gzip members are one
/// stream, as gunzip reads them.
class gzip_inflater {
public:
    gzip_inflater(std::string_view in, const std::string& name) : name_(name) {
        z_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
        z_.avail_in = 0;
        rest_ = in.size();
        ok_ = inflateInit2(&z_, 15 + 16) == Z_OK;  // 15 + 16: gzip wrapper
    }
    gzip_inflater(const gzip_inflater&) = delete;
    gzip_inflater& operator=(const gzip_inflater&) = delete;
    ~gzip_inflater() {
        if (ok_) inflateEnd(&z_);
    }
    /// True once the last member has ended and no input is left.
    bool finished() const noexcept { return finished_; }
    /// Inflates into `out` until it holds `limit` bytes or the stream ends.
    /// Errors: parse_error for corrupt or truncated data; io_error when memory runs out.
    result<void> inflate_into(byte_buffer& out, std::size_t limit) {
        if (!ok_) return fail(errc::io_error, name_ + ": cannot start inflating (zlib)");
        while (out.size() < limit && !finished_) {
            if (out.size() == out.capacity() && !out.grow_towards(limit))
                return fail(errc::io_error, name_ + ": not enough memory to inflate it (" + std::to_string(out.size()) +
                                                " bytes so far)");
            if (z_.avail_in == 0 && rest_ > 0) {
                const std::size_t take = std::min<std::size_t>(rest_, 1u << 30);  // avail_in is 32-bit
                z_.avail_in = static_cast<uInt>(take);
                rest_ -= take;
            }
            const std::size_t room = std::min<std::size_t>(out.capacity(), limit) - out.size();
            z_.next_out = reinterpret_cast<Bytef*>(out.data() + out.size());
            z_.avail_out = static_cast<uInt>(std::min<std::size_t>(room, 1u << 30));
            const uInt before = z_.avail_out;
            const int rc = inflate(&z_, Z_NO_FLUSH);
            out.set_size(out.size() + (before - z_.avail_out));
            if (rc == Z_STREAM_END) {
                if (z_.avail_in == 0 && rest_ == 0) {
                    finished_ = true;
                } else if (z_.avail_in >= 2 ? (z_.next_in[0] == 0x1f && z_.next_in[1] == 0x8b) : true) {
                    if (inflateReset(&z_) != Z_OK) return fail(errc::parse_error, name_ + ": corrupt gzip data");
                } else {
                    return fail(errc::parse_error,
                                name_ + ": data after the end of the gzip stream, at compressed byte offset " +
                                    std::to_string(z_.total_in));
                }
            } else if (rc == Z_BUF_ERROR && z_.avail_in == 0 && rest_ == 0) {
                return fail(errc::parse_error,
                            name_ + ": truncated gzip data (" + std::to_string(out.size()) + " bytes inflated)");
            } else if (rc != Z_OK && rc != Z_BUF_ERROR) {
                return fail(errc::parse_error,
                            name_ + ": corrupt gzip data: " + (z_.msg ? z_.msg : "zlib error " + std::to_string(rc)));
            }
        }
        return {};
    }

private:
    z_stream z_{};
    std::size_t rest_ = 0;
    std::string name_;
    bool ok_ = false, finished_ = false;
};
#endif

/// Decodes the samples that follow the header: exactly the declared count, no more, no less.
inline result<dense_grid<float>> inr_samples(const inr_header& h, std::string_view bytes, const std::string& name) {
    const std::uint64_t declared = h.sample_bytes();
    const std::uint64_t have = bytes.size() - h.header_bytes;
    if (have < declared)
        return fail(errc::parse_error, name + ": truncated: the header promises " + std::to_string(declared) +
                                           " bytes of samples, the file holds " + std::to_string(have));
    if (have > declared)
        return fail(errc::parse_error,
                    name + ": " + std::to_string(have - declared) + " bytes after the " + std::to_string(declared) +
                        " bytes of samples the header declares (wrong dimensions, or a corrupt file)");
    const std::size_t n = h.geometry.size(), sample_bytes = h.bits / 8;
    const char* data = bytes.data() + h.header_bytes;
    const bool swap = sample_bytes > 1 && (h.big_endian != (std::endian::native == std::endian::big));
    auto convert = [&](auto tag) -> result<dense_grid<float>> {
        using V = decltype(tag);
        auto g = detail::samples_to_grid<V>(data, h.geometry, swap, name);
        if (!g) return g.error();
        if constexpr (std::is_same_v<V, float>) {
            return std::move(*g);
        } else {
            dense_grid<float> out(h.geometry);
            for (std::size_t q = 0; q < n; ++q) out.data()[q] = static_cast<float>(g->data()[q]);
            return out;
        }
    };
    if (h.type == "float") return h.bits == 32 ? convert(float{}) : convert(double{});
    const bool sign = h.type == "signed fixed";
    switch (h.bits) {
        case 8: return sign ? convert(std::int8_t{}) : convert(std::uint8_t{});
        case 16: return sign ? convert(std::int16_t{}) : convert(std::uint16_t{});
        default: return sign ? convert(std::int32_t{}) : convert(std::uint32_t{});
    }
}

}  // namespace detail

/// Parses INRIMAGE-4 bytes (optionally gzip-compressed) into float samples; see read_inr.
/// `name` is the file name for messages. Complexity: O(N) for N samples.
inline result<dense_grid<float>> parse_inr(std::string_view bytes, const std::string& name) {
    if (!detail::is_gzip(bytes)) {
        auto h = parse_inr_header(bytes, name);
        if (!h) return h.error();
        return detail::inr_samples(*h, bytes, name);
    }
#if defined(HMIRA_HAS_ZLIB)
    // Header first, then no more than the samples it declares plus one byte (to tell that
    // there is more): a small file that inflates to gigabytes is refused after that much.
    detail::gzip_inflater z(bytes, name);
    detail::byte_buffer out;
    constexpr std::size_t header_window = 1 << 16;
    if (auto r = z.inflate_into(out, header_window); !r) return r.error();
    auto h = parse_inr_header(out.view(), name);
    if (!h) return h.error();
    const std::uint64_t want = h->header_bytes + h->sample_bytes() + 1;
    if (want > SIZE_MAX)
        return fail(errc::parse_error, name + ": the header declares more samples than memory can hold");
    if (auto r = z.inflate_into(out, static_cast<std::size_t>(want)); !r) return r.error();
    if (out.size() >= want)
        return fail(errc::parse_error,
                    name + ": the inflated data goes on past the " + std::to_string(h->sample_bytes()) +
                        " bytes of samples the header declares (wrong dimensions, a corrupt file, or a gzip bomb)");
    return detail::inr_samples(*h, out.view(), name);
#else
    return fail(errc::unsupported, name + ": gzip-compressed, but hmira was built without zlib");
#endif
}

/// Reads an INRIMAGE-4 volume (optionally gzip-compressed) into float samples, whatever the
/// stored type (8/16/32-bit integers, 32/64-bit floats). Spacing from VX/VY/VZ, origin from
/// TX/TY/TZ when present. A .gz file is inflated header first, then up to the samples the
/// header declares (plus one byte to detect more): memory stays bounded by the declared size.
/// Errors: io_error (cannot read, or a non-regular file longer than
/// options.max_input_bytes); parse_error for a missing magic or terminator, missing or bad
/// header values (dimensions, voxel sizes, origin, PIXSIZE), a file shorter than the header
/// promises ("truncated") or longer ("bytes after the ... samples"), corrupt gzip data, or
/// NaN samples; unsupported for vector volumes (VDIM > 1), other sample types, or .gz
/// without zlib. O(N).
inline result<dense_grid<float>> read_inr(const std::filesystem::path& path, const inr_options& options = {}) {
    auto file = detail::input_file::open(path, options.max_input_bytes);
    if (!file) return file.error();
    return parse_inr(file->text(), path.string());
}

}  // namespace hmira::io
