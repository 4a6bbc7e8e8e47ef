// fuzz/fuzz_volume.hpp
// The bodies of the volume and point fuzz targets, shared with the corpus regression test:
// parse the bytes as INR (plain, or gzip-compressed first), binvox or .xyz/.csv points. A
// refusal must be one non-empty line; an accepted volume must hold exactly what its header
// declares; accepted points must be finite. Returns "" or a description of the violated property.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <zlib.h>

#include <hmira/io/points.hpp>
#include <hmira/io/volume/binvox.hpp>
#include <hmira/io/volume/inr.hpp>

namespace hmira_fuzz {

/// "" for a good one-line message, else the problem.
inline std::string check_message(const std::string& m) {
    if (m.empty()) return "an error without a message";
    if (m.find('\n') != std::string::npos) return "a message of several lines: " + m;
    return "";
}

/// The bytes as one gzip member (fast level: the fuzzer wants executions, not ratio).
inline std::string gzip_bytes(std::string_view in) {
    z_stream z{};
    if (deflateInit2(&z, 1, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) return {};
    std::string out(deflateBound(&z, static_cast<uLong>(in.size())) + 64, '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(in.data()));
    z.avail_in = static_cast<uInt>(in.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    const int rc = deflate(&z, Z_FINISH);
    out.resize(z.total_out);
    deflateEnd(&z);
    return rc == Z_STREAM_END ? out : std::string();
}

/// INR: parse the bytes; with `gz`, parse them gzip-compressed (bytes that are gzip already
/// are parsed as they are, so real .gz seeds and bombs reach the inflater directly).
inline std::string one_inr(const std::uint8_t* data, std::size_t size, bool gz) {
    std::string_view bytes(reinterpret_cast<const char*>(data), size);
    std::string packed;
    if (gz && !hmira::io::detail::is_gzip(bytes)) {
        packed = gzip_bytes(bytes);
        bytes = packed;
    }
    auto g = hmira::io::parse_inr(bytes, "fuzz.inr");
    if (!g) return check_message(g.error().message);
    const auto d = g->dims();
    if (d[0] == 0 || d[1] == 0 || d[2] == 0) return "an accepted volume with a zero dimension";
    if (g->values().size() != d[0] * d[1] * d[2]) return "an accepted volume whose samples do not match its dims";
    for (float v : g->values())
        if (std::isnan(v)) return "an accepted volume with a NaN sample";
    return "";
}

/// binvox: parse; an accepted grid is a cube with finite geometry.
inline std::string one_binvox(const std::uint8_t* data, std::size_t size) {
    auto g = hmira::io::parse_binvox(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.binvox");
    if (!g) return check_message(g.error().message);
    const auto d = g->dims();
    if (d[0] == 0 || d[0] != d[1] || d[1] != d[2]) return "an accepted binvox grid that is not a cube";
    if (!std::isfinite(g->origin().x) || !(g->spacing().x > 0) || !std::isfinite(g->spacing().x))
        return "an accepted binvox grid with bad geometry";
    return "";
}

/// .xyz / .csv points: parse both ways; accepted points are finite.
inline std::string one_points(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (bool csv : {false, true}) {
        auto pts = hmira::io::parse_points_text(text, "fuzz.xyz", csv);
        if (!pts) {
            if (auto p = check_message(pts.error().message); !p.empty()) return p;
            continue;
        }
        for (const auto& p : *pts)
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                return "an accepted point that is not finite";
    }
    return "";
}

}  // namespace hmira_fuzz
