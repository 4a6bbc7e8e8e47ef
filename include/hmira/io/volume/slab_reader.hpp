// hmira/io/volume/slab_reader.hpp
// Reads z-slabs of an uncompressed volume file (.raw, or .inr without gzip) with pread, so a
// volume larger than memory can be meshed a few slices at a time (marching_cubes_by_slabs).
#pragma once

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "../../core/result.hpp"
#include "../../grids/voxel_grid.hpp"
#include "inr.hpp"
#include "raw.hpp"

namespace hmira::io {

/// The sample types a volume file can hold.
enum class sample_type { uint8, int8, uint16, int16, uint32, int32, float32, float64 };

/// Bytes per sample of a sample_type.
constexpr std::size_t sample_bytes(sample_type t) noexcept {
    switch (t) {
        case sample_type::uint8:
        case sample_type::int8: return 1;
        case sample_type::uint16:
        case sample_type::int16: return 2;
        case sample_type::uint32:
        case sample_type::int32:
        case sample_type::float32: return 4;
        case sample_type::float64: return 8;
    }
    return 1;
}

/// Where and how a volume file stores its samples.
struct volume_layout {
    grid_geometry geometry;                   ///< dimensions, origin and spacing
    sample_type type = sample_type::float32;  ///< stored sample type
    bool big_endian = false;                  ///< byte order of multi-byte samples
    std::uint64_t data_offset = 0;            ///< byte offset of sample (0, 0, 0)
};

/// The layout an uncompressed INRIMAGE-4 file declares, read from its first 64 KiB with pread.
/// Errors: io_error (cannot open or read); unsupported for a gzip-compressed file (read it whole
/// with read_inr); those of parse_inr_header().
inline result<volume_layout> read_inr_layout(const std::filesystem::path& path) {
    const std::string name = path.string();
    const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return fail(errc::io_error, name + ": cannot open: " + std::strerror(errno));
    std::string head(1 << 16, '\0');
    std::size_t got = 0;
    while (got < head.size()) {
        const auto n = ::pread(fd, head.data() + got, head.size() - got, static_cast<off_t>(got));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const int e = errno;
            ::close(fd);
            return fail(errc::io_error, name + ": read error: " + std::strerror(e));
        }
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    ::close(fd);
    head.resize(got);
    if (detail::is_gzip(head))
        return fail(errc::unsupported, name + ": gzip-compressed; it cannot be read slab by slab");
    auto h = parse_inr_header(head, name);
    if (!h) return h.error();
    volume_layout l{.geometry = h->geometry, .big_endian = h->big_endian, .data_offset = h->header_bytes};
    if (h->type == "float")
        l.type = h->bits == 32 ? sample_type::float32 : sample_type::float64;
    else {
        const bool sign = h->type == "signed fixed";
        l.type = h->bits == 8    ? (sign ? sample_type::int8 : sample_type::uint8)
                 : h->bits == 16 ? (sign ? sample_type::int16 : sample_type::uint16)
                                 : (sign ? sample_type::int32 : sample_type::uint32);
    }
    return l;
}

/// Reads z-slices of a regular volume file with pread: no mapping (so a file truncated behind
/// the reader's back gives an error, never SIGBUS) and no more memory than the slices asked for.
class volume_slab_reader {
public:
    /// Opens `path` and checks that it holds exactly the samples `layout` declares.
    /// Errors: io_error (cannot open, not a regular file); invalid_argument for a geometry
    /// check_grid_geometry() refuses; parse_error when the size is not data_offset + N x
    /// sample bytes, naming both sizes ("truncated" when short).
    static result<volume_slab_reader> open(const std::filesystem::path& path, const volume_layout& layout) {
        const std::string name = path.string();
        if (auto ok = check_grid_geometry(layout.geometry, name); !ok) return ok.error();
        volume_slab_reader r;
        r.name_ = name;
        r.layout_ = layout;
        const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0) return fail(errc::io_error, name + ": cannot open: " + std::strerror(errno));
        r.fd_ = std::shared_ptr<int>(new int(fd), [](int* p) {
            ::close(*p);
            delete p;
        });
        struct stat st {};
        if (::fstat(fd, &st) != 0) return fail(errc::io_error, name + ": cannot open: " + std::strerror(errno));
        if (!S_ISREG(st.st_mode))
            return fail(errc::io_error, name + ": not a regular file; it cannot be read slab by slab");
        const std::uint64_t have = static_cast<std::uint64_t>(st.st_size);
        const std::uint64_t want =
            layout.data_offset + std::uint64_t(layout.geometry.size()) * sample_bytes(layout.type);
        if (have != want) {
            const auto& d = layout.geometry.dims;
            return fail(
                errc::parse_error,
                name + ": holds " + std::to_string(have) + " bytes, but " + std::to_string(d[0]) + " x " +
                    std::to_string(d[1]) + " x " + std::to_string(d[2]) + " samples of " +
                    std::to_string(sample_bytes(layout.type)) + " bytes" +
                    (layout.data_offset ? " after a " + std::to_string(layout.data_offset) + "-byte header" : "") +
                    " need " + std::to_string(want) + (have < want ? " (truncated file?)" : ""));
        }
        return r;
    }

    /// The file's layout.
    const volume_layout& layout() const noexcept { return layout_; }

    /// Replaces `out` with z-slices k0 .. k0 + count - 1 converted to T (static_cast from the
    /// stored type), x fastest. Converts a bounded chunk at a time, so the only large buffer
    /// is `out`. O(count x nx x ny).
    /// Errors: invalid_argument for slices past the end; io_error for a read error or a file
    /// that shrank; parse_error naming the first NaN sample by its (i, j, k) in the whole grid.
    template <class T>
    result<void> read_slices(std::size_t k0, std::size_t count, std::vector<T>& out) const {
        const auto& d = layout_.geometry.dims;
        if (k0 > d[2] || count > d[2] - k0)
            return fail(errc::invalid_argument, name_ + ": slices " + std::to_string(k0) + " + " +
                                                    std::to_string(count) + " past " + std::to_string(d[2]));
        const std::size_t plane = d[0] * d[1], n = count * plane;
        out.resize(n);
        switch (layout_.type) {
            case sample_type::uint8: return convert<std::uint8_t>(k0, out);
            case sample_type::int8: return convert<std::int8_t>(k0, out);
            case sample_type::uint16: return convert<std::uint16_t>(k0, out);
            case sample_type::int16: return convert<std::int16_t>(k0, out);
            case sample_type::uint32: return convert<std::uint32_t>(k0, out);
            case sample_type::int32: return convert<std::int32_t>(k0, out);
            case sample_type::float32: return convert<float>(k0, out);
            case sample_type::float64: return convert<double>(k0, out);
        }
        return {};
    }

private:
    template <class V, class T>
    result<void> convert(std::size_t k0, std::vector<T>& out) const {
        const auto& d = layout_.geometry.dims;
        const std::size_t first = k0 * d[0] * d[1];
        const bool swap = sizeof(V) > 1 && (layout_.big_endian != (std::endian::native == std::endian::big));
        constexpr std::size_t chunk = std::size_t(1) << 20;  // samples per pread
        std::vector<V> buffer(std::min(chunk, out.size()));
        for (std::size_t done = 0; done < out.size();) {
            const std::size_t take = std::min(chunk, out.size() - done);
            auto* bytes = reinterpret_cast<char*>(buffer.data());
            const std::uint64_t at = layout_.data_offset + std::uint64_t(first + done) * sizeof(V);
            for (std::size_t got = 0; got < take * sizeof(V);) {
                const auto r = ::pread(*fd_, bytes + got, take * sizeof(V) - got, static_cast<off_t>(at + got));
                if (r < 0 && errno == EINTR) continue;
                if (r < 0)
                    return fail(errc::io_error, name_ + ": read error at byte " + std::to_string(at + got) + ": " +
                                                    std::strerror(errno));
                if (r == 0)
                    return fail(errc::io_error, name_ + ": the file shrank while being read (at byte " +
                                                    std::to_string(at + got) + ")");
                got += static_cast<std::size_t>(r);
            }
            for (std::size_t q = 0; q < take; ++q) {
                V v = buffer[q];
                if (swap) v = detail::byteswap_value(v);
                if constexpr (std::is_floating_point_v<V>) {
                    if (std::isnan(v)) {
                        const std::size_t s = first + done + q;
                        return fail(errc::parse_error,
                                    name_ + ": sample (" + std::to_string(s % d[0]) + ", " +
                                        std::to_string((s / d[0]) % d[1]) + ", " + std::to_string(s / (d[0] * d[1])) +
                                        ") is NaN",
                                    static_cast<long long>(s));
                    }
                }
                out[done + q] = static_cast<T>(v);
            }
            done += take;
        }
        return {};
    }

    std::string name_;
    volume_layout layout_;
    std::shared_ptr<int> fd_;
};

}  // namespace hmira::io
