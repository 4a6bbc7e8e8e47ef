// hmira/io/detail/stl_impl.hpp
// The machinery of stl.hpp: exact-equality welding of corners, the triangle collector, the
// ASCII parser and the writer's bytes for the triangles a mesh's faces plan into.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "../../concepts.hpp"
#include "../../core/huge_pages.hpp"
#include "../../core/result.hpp"
#include "../io_options.hpp"
#include "face_loops.hpp"
#include "files.hpp"
#include "polygon_soup.hpp"
#include "text_format.hpp"

namespace hmira::io::detail {

/// Exact-equality welding of float triples: open addressing over the bit patterns (with -0
/// turned into +0, so that values that compare equal weld). Expected O(1) per corner.
class stl_welder {
public:
    explicit stl_welder(std::size_t expected_vertices) {
        std::size_t cap = 1024;
        while (cap < 2 * expected_vertices) cap *= 2;
        slots_.assign(cap, slot{});
        mask_ = cap - 1;
    }
    /// The vertex index of p, adding it on first sight.
    std::uint32_t weld(const std::array<float, 3>& p) {
        std::array<std::uint32_t, 3> k{};
        for (std::size_t i = 0; i < 3; ++i) {
            const float x = p[i] == 0.0f ? 0.0f : p[i];
            k[i] = std::bit_cast<std::uint32_t>(x);
        }
        std::size_t i = hash(k) & mask_;
        for (;;) {
            slot& s = slots_[i];
            if (s.id == empty) {
                s = {k[0], k[1], k[2], static_cast<std::uint32_t>(points.size())};
                points.push_back(p);
                if (2 * points.size() > slots_.size()) grow();
                return static_cast<std::uint32_t>(points.size() - 1);
            }
            if (s.x == k[0] && s.y == k[1] && s.z == k[2]) return s.id;
            i = (i + 1) & mask_;
        }
    }
    std::vector<std::array<float, 3>> points;

private:
    static constexpr std::uint32_t empty = UINT32_MAX;
    struct slot {
        std::uint32_t x = 0, y = 0, z = 0, id = empty;
    };
    static std::size_t hash(const std::array<std::uint32_t, 3>& k) {
        std::uint64_t h = (static_cast<std::uint64_t>(k[0]) << 32 | k[1]) * 0x9E3779B97F4A7C15ull;
        h ^= (static_cast<std::uint64_t>(k[2]) + 0x632BE59BD9B4E019ull) * 0xC2B2AE3D27D4EB4Full;
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
    void grow() {
        std::vector<slot> old(slots_.size() * 2);
        old.swap(slots_);
        mask_ = slots_.size() - 1;
        for (const auto& s : old) {
            if (s.id == empty) continue;
            std::size_t i = hash({s.x, s.y, s.z}) & mask_;
            while (slots_[i].id != empty) i = (i + 1) & mask_;
            slots_[i] = s;
        }
    }
    std::vector<slot> slots_;
    std::size_t mask_ = 0;
};

/// Collects triangles, welding or not, and drops those whose corners weld together.
struct stl_builder {
    stl_builder(bool weld, std::size_t triangles) : welder(weld ? triangles / 2 + 16 : 0), weld(weld) {
        hmira::detail::reserve_huge(soup.indices, 3 * triangles);
        hmira::detail::reserve_huge(soup.face_offsets, triangles + 1);
        if (!weld) loose.reserve(3 * triangles);
    }
    void add(const std::array<std::array<float, 3>, 3>& t) {
        std::array<std::uint32_t, 3> id{};
        if (weld) {
            for (std::size_t k = 0; k < 3; ++k) id[k] = welder.weld(t[k]);
            if (id[0] == id[1] || id[1] == id[2] || id[0] == id[2]) {
                ++dropped;
                return;
            }
        } else {
            for (std::size_t k = 0; k < 3; ++k) {
                id[k] = static_cast<std::uint32_t>(loose.size());
                loose.push_back(t[k]);
            }
        }
        soup.indices.insert(soup.indices.end(), id.begin(), id.end());
        soup.face_offsets.push_back(soup.indices.size());
    }
    polygon_soup finish() {
        const auto& pts = weld ? welder.points : loose;
        soup.points.resize(pts.size());
        for (std::size_t i = 0; i < pts.size(); ++i) soup.points[i] = {pts[i][0], pts[i][1], pts[i][2]};
        return std::move(soup);
    }
    stl_welder welder;
    std::vector<std::array<float, 3>> loose;
    polygon_soup soup;
    bool weld;
    std::size_t dropped = 0;
};

inline bool stl_starts_with_solid(std::string_view text) {
    std::size_t i = 0;
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t' || text[i] == '\r' || text[i] == '\n')) ++i;
    return text.substr(i, 5) == "solid";
}

inline bool looks_binary(std::string_view text) {
    const auto probe = text.substr(0, 4096);
    return std::any_of(probe.begin(), probe.end(),
                       [](char ch) { return ch == '\0' || (static_cast<unsigned char>(ch) < 9); });
}

inline result<void> parse_stl_ascii(std::string_view text, const std::string& name, stl_builder& out,
                                    const read_options& options) {
    text_cursor c(text);
    progress_ticker ticker(options.progress, text.size());
    auto where = [&] { return name + ":" + std::to_string(c.line()); };
    auto expect = [&](std::string_view word, const char* context) -> result<void> {
        c.skip_space_and_newlines();
        if (c.at_end())
            return fail(errc::parse_error, where() + ": file ends " + context + " (expected '" + std::string(word) +
                                               "'; truncated file?)");
        const auto t = c.token();
        if (t != word)
            return fail(errc::parse_error, where() + ": expected '" + std::string(word) + "' " + context + ", found '" +
                                               std::string(t.substr(0, 40)) + "'");
        return {};
    };
    std::size_t facet = 0;
    bool in_solid = false;
    for (;;) {
        c.skip_space_and_newlines();
        if (c.at_end()) break;
        const auto t = c.token();
        if (t == "solid") {
            in_solid = true;
            c.next_line();  // the rest of the line is the solid's name
            continue;
        }
        if (t == "endsolid") {
            in_solid = false;
            c.next_line();
            continue;
        }
        if (t != "facet")
            return fail(errc::parse_error,
                        where() + ": expected 'facet' or 'endsolid', found '" + std::string(t.substr(0, 40)) + "'");
        if (!in_solid) return fail(errc::parse_error, where() + ": 'facet' outside 'solid' ... 'endsolid'");
        const std::string ctx = "in facet " + std::to_string(facet);
        if (auto r = expect("normal", ctx.c_str()); !r) return r;
        for (int k = 0; k < 3; ++k) {
            float x = 0;
            if (!c.number(x))
                return fail(errc::parse_error,
                            where() + ": facet " + std::to_string(facet) + " normal: " + describe_bad_number(c));
        }
        if (auto r = expect("outer", ctx.c_str()); !r) return r;
        if (auto r = expect("loop", ctx.c_str()); !r) return r;
        std::array<std::array<float, 3>, 3> tri{};
        for (std::size_t v = 0; v < 3; ++v) {
            c.skip_space_and_newlines();
            if (c.at_end())
                return fail(errc::parse_error,
                            where() + ": file ends in facet " + std::to_string(facet) + " (truncated file?)");
            const auto w = c.token();
            if (w != "vertex")
                return fail(errc::parse_error, where() + ": facet " + std::to_string(facet) + " has " +
                                                   std::to_string(v) + " vertices; STL facets need exactly 3 (found '" +
                                                   std::string(w.substr(0, 40)) + "')");
            for (auto& x : tri[v])
                if (!c.number(x))
                    return fail(errc::parse_error,
                                where() + ": facet " + std::to_string(facet) + " vertex: " + describe_bad_number(c));
            if (!all_finite(tri[v]))
                return fail(errc::parse_error, where() + ": facet " + std::to_string(facet) +
                                                   " has a vertex coordinate that is not finite (NaN or infinity)");
        }
        c.skip_space_and_newlines();
        if (c.peek_token() == "vertex")
            return fail(errc::parse_error, where() + ": facet " + std::to_string(facet) + " has more than 3 vertices");
        if (auto r = expect("endloop", ctx.c_str()); !r) return r;
        if (auto r = expect("endfacet", ctx.c_str()); !r) return r;
        out.add(tri);
        ++facet;
        if (!ticker.tick(c.offset())) return progress_ticker::cancelled(where());
    }
    if (in_solid) return fail(errc::parse_error, where() + ": file ends before 'endsolid' (truncated file?)");
    ticker.finish();
    return {};
}

/// Writes STL through `out`, with the triangles `plan` gives (detail::plan_stl_triangles);
/// facet normals are computed from the corners (zero for degenerate triangles).
template <class M, class T>
bool write_stl_planned(const M& mesh, std::ostream& stream, const stl_triangles<M, T>& plan,
                       const write_options& options) {
    using S = typename T::scalar;
    chunked_output out(stream);
    auto& b = out.buffer();
    const bool ascii = options.stl == stl_encoding::ascii;
    if (ascii) {
        b += "solid hmira\n";
    } else {
        if (plan.total > UINT32_MAX) return false;
        char header[80] = {};
        std::memcpy(header, "binary STL written by hmira", 27);
        b.append(header, 80);
        std::uint32_t n = static_cast<std::uint32_t>(plan.total);
        if constexpr (std::endian::native == std::endian::big) n = __builtin_bswap32(n);
        b.append(reinterpret_cast<const char*>(&n), 4);
    }
    auto put_float = [&](float x) {
        if constexpr (std::endian::native == std::endian::big)
            x = std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(x)));
        b.append(reinterpret_cast<const char*>(&x), 4);
    };
    auto put_triangle = [&](const std::array<vec3<S>, 3>& tri) {
        const auto n = normalized(cross(tri[1] - tri[0], tri[2] - tri[0]));
        if (ascii) {
            b += "  facet normal ";
            for (std::size_t k = 0; k < 3; ++k) {
                if (k) b += ' ';
                append_number(b, static_cast<float>(n[k]));
            }
            b += "\n    outer loop\n";
            for (const auto& q : tri) {
                b += "      vertex ";
                for (std::size_t k = 0; k < 3; ++k) {
                    if (k) b += ' ';
                    append_number(b, static_cast<float>(q[k]));
                }
                b += '\n';
            }
            b += "    endloop\n  endfacet\n";
        } else {
            for (std::size_t k = 0; k < 3; ++k) put_float(static_cast<float>(n[k]));
            for (const auto& q : tri)
                for (std::size_t k = 0; k < 3; ++k) put_float(static_cast<float>(q[k]));
            b.append(2, '\0');
        }
    };
    auto at = [&](typename T::vertex_handle v) { return static_cast<vec3<S>>(T::position(mesh, v)); };
    std::size_t planned_face = 0, next_triangle = 0;
    std::array<vec3<S>, 3> tri;
    for (auto f : T::faces(mesh)) {
        std::size_t k = 0;
        bool plain = !has_inner_rings<M, T>(mesh, f);
        if (plain)
            for (auto v : T::face_vertices(mesh, f)) {
                if (k == 3) {
                    plain = false;
                    break;
                }
                tri[k++] = at(v);
            }
        if (plain && k == 3) {
            put_triangle(tri);
        } else {
            // The plan lists the faces that are not plain triangles in this same order.
            const std::size_t end = next_triangle + plan.counts[planned_face++];
            for (; next_triangle < end; ++next_triangle) {
                const auto& t = plan.triangles[next_triangle];
                put_triangle({at(t[0]), at(t[1]), at(t[2])});
            }
        }
        if (!out.maybe_flush()) return false;
    }
    if (ascii) b += "endsolid hmira\n";
    return out.flush();
}

}  // namespace hmira::io::detail
