// hmira/io/detail/zip.hpp
// The ZIP container of 3MF, and the zlib blocks of compressed .vtp arrays. Reading walks the
// central directory and reads one named entry (stored, or deflated when zlib is available),
// refusing an entry whose declared size exceeds the caller's limit and one that inflates to
// more (or less) than it declares, so a zip bomb costs at most the limit. Writing makes a
// ZIP of whole in-memory entries (deflated with zlib when available, else stored).
// zlib is an optional part: it is used when the including program defines HMIRA_HAS_ZLIB (the
// CMake target hmira::zlib does, and links it); without it, deflated data is refused.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "../../core/result.hpp"
#include "json.hpp"  // printable

#if defined(HMIRA_HAS_ZLIB)
#include <zlib.h>
#endif

namespace hmira::io::detail {

/// Whether this build reads and writes deflated data.
inline constexpr bool has_zlib =
#if defined(HMIRA_HAS_ZLIB)
    true;
#else
    false;
#endif

inline std::uint32_t le_u32(const char* p) {
    const auto* u = reinterpret_cast<const unsigned char*>(p);
    return std::uint32_t(u[0]) | std::uint32_t(u[1]) << 8 | std::uint32_t(u[2]) << 16 | std::uint32_t(u[3]) << 24;
}
inline std::uint16_t le_u16(const char* p) {
    const auto* u = reinterpret_cast<const unsigned char*>(p);
    return static_cast<std::uint16_t>(u[0] | u[1] << 8);
}
inline std::uint64_t le_u64(const char* p) { return le_u32(p) | std::uint64_t(le_u32(p + 4)) << 32; }

/// CRC-32 (the ZIP polynomial).
inline std::uint32_t crc32_of(std::string_view bytes) {
#if defined(HMIRA_HAS_ZLIB)
    uLong crc = ::crc32(0L, Z_NULL, 0);
    std::size_t at = 0;
    while (at < bytes.size()) {
        const std::size_t n = std::min<std::size_t>(bytes.size() - at, std::size_t{1} << 30);
        crc = ::crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(n));
        at += n;
    }
    return static_cast<std::uint32_t>(crc);
#else
    static const auto table = [] {
        std::array<std::uint32_t, 256> t{};
        for (std::uint32_t i = 0; i < 256; ++i) {
            std::uint32_t c = i;
            for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
            t[i] = c;
        }
        return t;
    }();
    std::uint32_t c = 0xffffffffu;
    for (unsigned char b : bytes) c = table[(c ^ b) & 0xff] ^ (c >> 8);
    return c ^ 0xffffffffu;
#endif
}

/// The most bytes `packed` bytes of deflate data can inflate to (1032 to 1, plus slack).
inline std::uint64_t deflate_bound(std::uint64_t packed) { return packed * 1032 + 1024; }

/// Inflates `in` (raw deflate when `raw`, else zlib-wrapped) into exactly `size` bytes: more or
/// fewer is an error naming `where`. errc::unsupported without zlib.
inline result<std::string> inflate_exactly(std::string_view in, std::uint64_t size, bool raw,
                                           const std::string& where) {
#if defined(HMIRA_HAS_ZLIB)
    std::string out(static_cast<std::size_t>(size), '\0');
    z_stream z{};
    if (inflateInit2(&z, raw ? -15 : 15) != Z_OK) return fail(errc::io_error, where + ": cannot start zlib");
    std::size_t in_at = 0, out_at = 0;
    int rc = Z_OK;
    constexpr std::size_t chunk = std::size_t{1} << 30;
    while (rc == Z_OK) {
        if (z.avail_in == 0 && in_at < in.size()) {
            const std::size_t n = std::min(chunk, in.size() - in_at);
            z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data() + in_at));
            z.avail_in = static_cast<uInt>(n);
            in_at += n;
        }
        const std::size_t n = std::min(chunk, out.size() - out_at);
        // One spare byte past the declared size shows a stream that would inflate to more.
        char spare = 0;
        z.next_out = reinterpret_cast<Bytef*>(n ? out.data() + out_at : &spare);
        z.avail_out = static_cast<uInt>(n ? n : 1);
        const uInt before = z.avail_out;
        rc = ::inflate(&z, Z_NO_FLUSH);
        const std::size_t produced = before - z.avail_out;
        if (n == 0 && produced) {
            inflateEnd(&z);
            return fail(errc::parse_error,
                        where + ": inflates to more than the " + std::to_string(size) + " bytes it declares (refused)");
        }
        out_at += produced;
        if (rc == Z_BUF_ERROR && z.avail_in == 0 && in_at == in.size()) break;
        if (rc == Z_BUF_ERROR) rc = Z_OK;
    }
    const std::string msg = z.msg ? z.msg : "";
    inflateEnd(&z);
    if (rc != Z_STREAM_END)
        return fail(errc::parse_error, where + ": corrupt or truncated compressed data" +
                                           (msg.empty() ? std::string() : " (" + msg + ")"));
    if (out_at != size)
        return fail(errc::parse_error, where + ": inflates to " + std::to_string(out_at) + " bytes, not the " +
                                           std::to_string(size) + " it declares");
    return out;
#else
    (void)in, (void)size, (void)raw;
    return fail(errc::unsupported, where + ": compressed data, and this build has no zlib (HMIRA_HAS_ZLIB)");
#endif
}

/// Deflates `in` (raw deflate when `raw`, else zlib-wrapped); empty without zlib.
inline std::string deflate_bytes(std::string_view in, bool raw, int level = 1) {
#if defined(HMIRA_HAS_ZLIB)
    if (in.size() > 0xffffffffu) return {};  // stored instead
    z_stream z{};
    if (deflateInit2(&z, level, Z_DEFLATED, raw ? -15 : 15, 8, Z_DEFAULT_STRATEGY) != Z_OK) return {};
    std::string out(deflateBound(&z, static_cast<uLong>(in.size())), '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
    z.avail_in = static_cast<uInt>(in.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    const int rc = ::deflate(&z, Z_FINISH);
    out.resize(z.total_out);
    deflateEnd(&z);
    return rc == Z_STREAM_END ? out : std::string();
#else
    (void)in, (void)raw, (void)level;
    return {};
#endif
}

/// One entry of a ZIP's central directory.
struct zip_entry {
    std::string name;
    std::uint64_t compressed = 0, size = 0, local_offset = 0;
    std::uint32_t crc = 0;
    std::uint16_t method = 0, flags = 0;
};

/// The central directory of a ZIP held in memory, every offset and size checked against the
/// file. Errors name the archive and the byte offset.
inline result<std::vector<zip_entry>> zip_directory(std::string_view data, const std::string& name) {
    auto bad = [&](std::size_t at, const std::string& what) {
        return fail(errc::parse_error, name + ": byte offset " + std::to_string(at) + ": " + what,
                    static_cast<long long>(at));
    };
    if (data.size() < 22 || le_u32(data.data()) != 0x04034b50u)
        return bad(0, "not a ZIP archive (no local file header signature)");
    std::size_t eocd = std::string_view::npos;
    const std::size_t lowest = data.size() > 65557 ? data.size() - 65557 : 0;
    for (std::size_t at = data.size() - 22 + 1; at-- > lowest;)
        if (le_u32(data.data() + at) == 0x06054b50u) {
            eocd = at;
            break;
        }
    if (eocd == std::string_view::npos) return bad(data.size(), "no end of central directory record (truncated?)");
    std::uint64_t count = le_u16(data.data() + eocd + 10);
    std::uint64_t dir_size = le_u32(data.data() + eocd + 12), dir_offset = le_u32(data.data() + eocd + 16);
    if (eocd >= 20 && le_u32(data.data() + eocd - 20) == 0x07064b50u) {  // ZIP64 locator
        const std::uint64_t at = le_u64(data.data() + eocd - 20 + 8);
        if (data.size() < 56 || at > data.size() - 56 || le_u32(data.data() + at) != 0x06064b50u)
            return bad(eocd - 20, "ZIP64 end of central directory record out of bounds");
        count = le_u64(data.data() + at + 32);
        dir_size = le_u64(data.data() + at + 40);
        dir_offset = le_u64(data.data() + at + 48);
    }
    if (dir_offset > data.size() || dir_size > data.size() - dir_offset)
        return bad(eocd, "central directory (offset " + std::to_string(dir_offset) + ", " + std::to_string(dir_size) +
                             " bytes) runs past the file");
    if (count > dir_size / 46) return bad(eocd, std::to_string(count) + " entries cannot fit the central directory");
    std::vector<zip_entry> entries;
    entries.reserve(static_cast<std::size_t>(count));
    std::size_t at = static_cast<std::size_t>(dir_offset);
    const std::size_t end = static_cast<std::size_t>(dir_offset + dir_size);
    for (std::uint64_t i = 0; i < count; ++i) {
        if (end - at < 46 || le_u32(data.data() + at) != 0x02014b50u)
            return bad(at, "central directory entry " + std::to_string(i) + " is malformed");
        zip_entry e;
        e.flags = le_u16(data.data() + at + 8);
        e.method = le_u16(data.data() + at + 10);
        e.crc = le_u32(data.data() + at + 16);
        e.compressed = le_u32(data.data() + at + 20);
        e.size = le_u32(data.data() + at + 24);
        const std::size_t name_len = le_u16(data.data() + at + 28), extra_len = le_u16(data.data() + at + 30),
                          comment_len = le_u16(data.data() + at + 32);
        e.local_offset = le_u32(data.data() + at + 42);
        if (end - at - 46 < name_len + extra_len + comment_len)
            return bad(at, "central directory entry " + std::to_string(i) + " runs past the directory");
        e.name.assign(data.substr(at + 46, name_len));
        // ZIP64 sizes and offset, in that order, for the fields saturated at 0xffffffff.
        for (std::size_t x = at + 46 + name_len, xend = x + extra_len; xend - x >= 4;) {
            const std::uint16_t id = le_u16(data.data() + x), len = le_u16(data.data() + x + 2);
            if (len > xend - x - 4) break;
            if (id == 1) {
                std::size_t f = x + 4;
                auto take = [&](std::uint64_t& field) {
                    if (field != 0xffffffffu || f + 8 > x + 4 + len) return;
                    field = le_u64(data.data() + f);
                    f += 8;
                };
                take(e.size), take(e.compressed), take(e.local_offset);
            }
            x += 4 + len;
        }
        entries.push_back(std::move(e));
        at += 46 + name_len + extra_len + comment_len;
    }
    return entries;
}

/// The bytes of `entry`, inflated if deflated, its CRC checked. A declared size over `limit`
/// is refused before anything is allocated.
inline result<std::string> zip_read(std::string_view data, const zip_entry& entry, const std::string& name,
                                    std::uint64_t limit) {
    const std::string where = name + ": entry '" + printable(entry.name.substr(0, 200)) + "'";
    if (entry.flags & 1) return fail(errc::unsupported, where + " is encrypted");
    if (entry.size > limit)
        return fail(errc::parse_error, where + " declares " + std::to_string(entry.size) +
                                           " bytes, over the input limit of " + std::to_string(limit) + " (refused)");
    const std::uint64_t at = entry.local_offset;
    if (at > data.size() || data.size() - at < 30 || le_u32(data.data() + at) != 0x04034b50u)
        return fail(errc::parse_error, where + ": local header offset " + std::to_string(at) + " is out of bounds");
    const std::uint64_t body = at + 30 + le_u16(data.data() + at + 26) + le_u16(data.data() + at + 28);
    if (body > data.size() || entry.compressed > data.size() - body)
        return fail(errc::parse_error, where + ": " + std::to_string(entry.compressed) + " bytes from offset " +
                                           std::to_string(body) + " run past the end of the archive");
    const std::string_view packed =
        data.substr(static_cast<std::size_t>(body), static_cast<std::size_t>(entry.compressed));
    // Deflate makes at most 1032 bytes of one (RFC 1951 block limits): a larger claim is a lie.
    if (entry.method == 8 && entry.size > deflate_bound(entry.compressed))
        return fail(errc::parse_error, where + " declares " + std::to_string(entry.size) + " bytes from " +
                                           std::to_string(entry.compressed) +
                                           " deflated ones, more than deflate makes");
    std::string out;
    if (entry.method == 0) {
        if (entry.compressed != entry.size) return fail(errc::parse_error, where + ": stored entry whose sizes differ");
        out.assign(packed);
    } else if (entry.method == 8) {
        auto inflated = inflate_exactly(packed, entry.size, true, where);
        if (!inflated) return inflated.error();
        out = std::move(*inflated);
    } else {
        return fail(errc::unsupported,
                    where + " uses compression method " + std::to_string(entry.method) + " (only stored and deflate)");
    }
    if (crc32_of(out) != entry.crc) return fail(errc::parse_error, where + ": CRC-32 mismatch (corrupt data)");
    return out;
}

/// A ZIP of the given (name, bytes) entries, deflated when `deflate` and zlib is available, else
/// stored. At most 4 GiB in all (no ZIP64 records are written).
inline std::string zip_archive(const std::vector<std::pair<std::string, std::string_view>>& files,
                               bool deflate = true) {
    std::string out, directory;
    auto u16 = [](std::string& s, std::uint32_t v) { s += char(v & 0xff), s += char((v >> 8) & 0xff); };
    auto u32 = [&](std::string& s, std::uint64_t v) {
        const auto x = static_cast<std::uint32_t>(v);
        u16(s, x & 0xffff), u16(s, x >> 16);
    };
    for (const auto& entry : files) {
        const std::string& file = entry.first;
        const std::string_view bytes = entry.second;
        const std::uint32_t crc = crc32_of(bytes);
        std::string packed = deflate ? deflate_bytes(bytes, true, 1) : std::string();
        const bool deflated = !packed.empty();
        const std::string_view body = deflated ? std::string_view(packed) : bytes;
        const std::uint16_t method = deflated ? 8 : 0;
        const std::uint64_t offset = out.size();
        auto header = [&](std::string& s, bool central) {
            u32(s, central ? 0x02014b50u : 0x04034b50u);
            if (central) u16(s, 20);
            u16(s, 20), u16(s, 0), u16(s, method), u16(s, 0), u16(s, 0x21);  // version, flags, method, 1980-01-01
            u32(s, crc), u32(s, method ? body.size() : bytes.size()), u32(s, bytes.size());
            u16(s, static_cast<std::uint32_t>(file.size())), u16(s, 0);
            if (central) u16(s, 0), u16(s, 0), u16(s, 0), u32(s, 0), u32(s, offset);
            s += file;
        };
        header(out, false);
        out += method ? body : bytes;
        header(directory, true);
    }
    const std::uint64_t dir_offset = out.size();
    out += directory;
    u32(out, 0x06054b50u), u16(out, 0), u16(out, 0);
    u16(out, static_cast<std::uint32_t>(files.size())), u16(out, static_cast<std::uint32_t>(files.size()));
    u32(out, directory.size()), u32(out, dir_offset), u16(out, 0);
    return out;
}

}  // namespace hmira::io::detail
