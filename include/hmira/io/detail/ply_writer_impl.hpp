// hmira/io/detail/ply_writer_impl.hpp
// The machinery of ply_writer.hpp: the PLY bytes of a mesh, header then vertices then faces,
// in ASCII or in binary of either byte order.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <ostream>
#include <string>
#include <type_traits>
#include <vector>

#include "../../concepts.hpp"
#include "../io_options.hpp"
#include "face_loops.hpp"
#include "files.hpp"
#include "ply_types.hpp"
#include "polygon_soup.hpp"
#include "text_format.hpp"

namespace hmira::io::detail {

/// The PLY bytes of a mesh that refuse_unwritable accepted; false when the stream failed.
template <class M, class T>
bool put_ply(const M& mesh, std::ostream& stream, const write_options& options) {
    using S = typename T::scalar;
    detail::chunked_output out(stream);
    auto& b = out.buffer();
    const auto attr = detail::find_attributes<M, T>(mesh, options);
    const bool use_float = options.ply_coordinates == ply_scalar::float32 ||
                           (options.ply_coordinates == ply_scalar::mesh && sizeof(S) <= sizeof(float));
    std::size_t max_degree = 0;
    for (auto f : T::faces(mesh)) {
        std::size_t k = 0;
        for (auto v : T::face_vertices(mesh, f)) (void)v, ++k;
        max_degree = std::max(max_degree, k);
    }
    const bool wide_count = max_degree > 255;
    b += "ply\nformat ";
    b += options.ply == ply_encoding::ascii                  ? "ascii"
         : options.ply == ply_encoding::binary_little_endian ? "binary_little_endian"
                                                             : "binary_big_endian";
    b += " 1.0\ncomment written by hmira\nelement vertex ";
    detail::append_number(b, std::uint64_t{T::vertex_count(mesh)});
    const char* ct = use_float ? "float" : "double";
    for (const char* axis : {"x", "y", "z"}) b += std::string("\nproperty ") + ct + " " + axis;
    if (attr.normals)
        for (const char* axis : {"nx", "ny", "nz"}) b += std::string("\nproperty float ") + axis;
    if (attr.colors)
        for (const char* ch : {"red", "green", "blue", "alpha"}) b += std::string("\nproperty uchar ") + ch;
    b += "\nelement face ";
    detail::append_number(b, std::uint64_t{T::face_count(mesh)});
    b += wide_count ? "\nproperty list uint int vertex_indices\nend_header\n"
                    : "\nproperty list uchar int vertex_indices\nend_header\n";

    const bool ascii = options.ply == ply_encoding::ascii;
    const bool swap =
        (options.ply == ply_encoding::binary_little_endian) != (std::endian::native == std::endian::little);
    auto put = [&](auto value) {
        if (swap) {
            using V = decltype(value);
            using U = std::conditional_t<
                sizeof(V) == 1, std::uint8_t,
                std::conditional_t<sizeof(V) == 2, std::uint16_t,
                                   std::conditional_t<sizeof(V) == 4, std::uint32_t, std::uint64_t>>>;
            U u;
            std::memcpy(&u, &value, sizeof u);
            u = detail::ply_swap(u);
            b.append(reinterpret_cast<const char*>(&u), sizeof u);
        } else {
            b.append(reinterpret_cast<const char*>(&value), sizeof value);
        }
    };
    const auto number = detail::dense_vertex_numbers<M, T>(mesh);
    for (auto v : T::vertices(mesh)) {
        const auto p = static_cast<vec3<S>>(T::position(mesh, v));
        const auto vi = T::vertex_index(mesh, v);
        if (ascii) {
            for (std::size_t k = 0; k < 3; ++k) {
                if (k) b += ' ';
                if (use_float)
                    detail::append_number(b, static_cast<float>(p[k]));
                else
                    detail::append_number(b, static_cast<double>(p[k]));
            }
            if (attr.normals)
                for (std::size_t k = 0; k < 3; ++k) b += ' ', detail::append_number(b, attr.normals[vi][k]);
            if (attr.colors)
                for (std::size_t k = 0; k < 4; ++k)
                    b += ' ', detail::append_number(b, std::uint64_t{attr.colors[vi][k]});
            b += '\n';
        } else {
            for (std::size_t k = 0; k < 3; ++k) {
                if (use_float)
                    put(static_cast<float>(p[k]));
                else
                    put(static_cast<double>(p[k]));
            }
            if (attr.normals)
                for (std::size_t k = 0; k < 3; ++k) put(attr.normals[vi][k]);
            if (attr.colors)
                for (std::size_t k = 0; k < 4; ++k) put(attr.colors[vi][k]);
        }
        if (!out.maybe_flush()) return false;
    }
    std::vector<std::uint32_t> loop;
    for (auto f : T::faces(mesh)) {
        loop.clear();
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(number[T::vertex_index(mesh, v)]);
        if (ascii) {
            detail::append_number(b, std::uint64_t{loop.size()});
            for (auto i : loop) b += ' ', detail::append_number(b, i);
            b += '\n';
        } else {
            if (wide_count)
                put(static_cast<std::uint32_t>(loop.size()));
            else
                put(static_cast<std::uint8_t>(loop.size()));
            for (auto i : loop) put(static_cast<std::int32_t>(i));
        }
        if (!out.maybe_flush()) return false;
    }
    return out.flush();
}

}  // namespace hmira::io::detail
