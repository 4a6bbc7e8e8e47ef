// hmira/io/detail/threemf_impl.hpp
// The machinery of threemf.hpp: the model part found through the package relationships, its
// objects (meshes, or components with transforms) and build items, instantiated into one soup
// with every reference, index and transform checked, and the writer's three package parts.
#pragma once

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "../../core/result.hpp"
#include "face_loops.hpp"
#include "json.hpp"
#include "polygon_soup.hpp"
#include "text_format.hpp"
#include "xml.hpp"
#include "zip.hpp"

namespace hmira::io::detail {

/// A 3MF affine transform, row-vector convention: p' = p * M, stored m00 m01 m02 m10 ... m32.
using threemf_transform = std::array<double, 12>;
inline constexpr threemf_transform threemf_identity{1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0};

/// a then b.
inline threemf_transform compose(const threemf_transform& a, const threemf_transform& b) {
    threemf_transform r{};
    for (int row = 0; row < 4; ++row)
        for (int c = 0; c < 3; ++c) {
            double s = row == 3 ? b[9 + c] : 0;
            for (int k = 0; k < 3; ++k) s += a[row * 3 + k] * b[k * 3 + c];
            r[row * 3 + c] = s;
        }
    return r;
}

struct threemf_component {
    std::uint64_t object = 0;
    threemf_transform transform = threemf_identity;
};

struct threemf_object {
    std::vector<std::array<double, 3>> vertices;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<threemf_component> components;
};

/// The model part named by _rels/.rels (the 3D model relationship), or 3D/3dmodel.model.
inline result<std::string> threemf_model_name(std::string_view zip, const std::vector<zip_entry>& entries,
                                              const std::string& name, std::uint64_t limit) {
    for (const auto& e : entries) {
        if (e.name != "_rels/.rels") continue;
        auto rels = zip_read(zip, e, name, limit);
        if (!rels) return rels.error();
        xml_reader x(*rels, name + " (_rels/.rels)", 16);
        for (;;) {
            auto ev = x.next();
            if (!ev) return ev.error();
            if (*ev == xml_event::done) break;
            if (*ev != xml_event::start || x.name != "Relationship") continue;
            const auto* type = x.find("Type");
            const auto* target = x.find("Target");
            if (type && target && type->ends_with("/3dmodel")) {
                std::string t = xml_decode(*target);
                while (t.starts_with("/")) t.erase(0, 1);
                return t;
            }
        }
    }
    return std::string("3D/3dmodel.model");
}

inline bool threemf_number(std::string_view s, double& out) {
    while (!s.empty() && xml_reader::is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && xml_reader::is_space(s.back())) s.remove_suffix(1);
    return parse_double(s, out) && std::isfinite(out);
}

inline result<threemf_transform> threemf_parse_transform(const xml_reader& x, const std::string& where) {
    const auto* t = x.find("transform");
    if (!t) return threemf_identity;
    threemf_transform m{};
    std::size_t pos = 0;
    for (double& v : m) {
        while (pos < t->size() && xml_reader::is_space((*t)[pos])) ++pos;
        const std::size_t begin = pos;
        while (pos < t->size() && !xml_reader::is_space((*t)[pos])) ++pos;
        if (!threemf_number(t->substr(begin, pos - begin), v))
            return x.bad(where + ": transform is not 12 finite numbers");
    }
    while (pos < t->size() && xml_reader::is_space((*t)[pos])) ++pos;
    if (pos != t->size()) return x.bad(where + ": transform has more than 12 numbers");
    return m;
}

inline result<std::uint64_t> threemf_index(const xml_reader& x, const char* key, const std::string& where) {
    const auto* v = x.find(key);
    std::uint64_t n = 0;
    if (!v) return x.bad(where + " has no " + key);
    const auto r = std::from_chars(v->data(), v->data() + v->size(), n);
    if (v->empty() || r.ec != std::errc() || r.ptr != v->data() + v->size())
        return x.bad(where + ": " + key + "=\"" + printable(std::string(v->substr(0, 32))) + "\" is not an index");
    return n;
}

/// The objects and build items of a model part.
struct threemf_model {
    std::vector<threemf_object> objects;
    std::unordered_map<std::uint64_t, std::size_t> by_id;
    std::vector<threemf_component> items;
};

inline result<threemf_model> threemf_parse_model(std::string_view text, const std::string& name) {
    xml_reader x(text, name, 64);
    threemf_model model;
    threemf_object* object = nullptr;
    std::uint64_t object_id = 0;
    bool in_build = false, root = false;
    for (;;) {
        auto ev = x.next();
        if (!ev) return ev.error();
        if (*ev == xml_event::done) break;
        if (*ev == xml_event::end) {
            if (x.name == "object") object = nullptr;
            if (x.name == "build") in_build = false;
            continue;
        }
        if (*ev != xml_event::start) continue;
        const std::string_view tag = x.name;
        if (!root) {
            if (tag != "model") return x.bad("the root element is not <model>");
            root = true;
            continue;
        }
        if (object && tag == "vertex") {
            std::array<double, 3> p{};
            int seen = 0;
            for (const auto& a : x.attributes) {
                const int k = a.name == "x" ? 0 : a.name == "y" ? 1 : a.name == "z" ? 2 : -1;
                if (k < 0) continue;
                if (!threemf_number(a.value, p[static_cast<std::size_t>(k)]))
                    return x.bad("object " + std::to_string(object_id) + ": vertex " +
                                 std::to_string(object->vertices.size()) +
                                 " has a coordinate that is not a finite number");
                seen |= 1 << k;
            }
            if (seen != 7)
                return x.bad("object " + std::to_string(object_id) + ": vertex " +
                             std::to_string(object->vertices.size()) + " lacks x, y or z");
            object->vertices.push_back(p);
        } else if (object && tag == "triangle") {
            std::array<std::uint32_t, 3> t{};
            int seen = 0;
            for (const auto& a : x.attributes) {
                const int k = a.name == "v1" ? 0 : a.name == "v2" ? 1 : a.name == "v3" ? 2 : -1;
                if (k < 0) continue;
                std::uint64_t v = 0;
                const auto r = std::from_chars(a.value.data(), a.value.data() + a.value.size(), v);
                if (a.value.empty() || r.ec != std::errc() || r.ptr != a.value.data() + a.value.size() ||
                    v >= object->vertices.size())
                    return x.bad("object " + std::to_string(object_id) + ": triangle " +
                                 std::to_string(object->triangles.size()) + " names a vertex out of range [0, " +
                                 std::to_string(object->vertices.size()) + ")");
                t[static_cast<std::size_t>(k)] = static_cast<std::uint32_t>(v);
                seen |= 1 << k;
            }
            if (seen != 7)
                return x.bad("object " + std::to_string(object_id) + ": triangle " +
                             std::to_string(object->triangles.size()) + " lacks v1, v2 or v3");
            object->triangles.push_back(t);
        } else if (tag == "object") {
            auto id = threemf_index(x, "id", "<object>");
            if (!id) return id.error();
            if (!model.by_id.emplace(*id, model.objects.size()).second)
                return x.bad("object id " + std::to_string(*id) + " is used twice");
            model.objects.emplace_back();
            object = &model.objects.back();
            object_id = *id;
        } else if (object && tag == "component") {
            const std::string where = "object " + std::to_string(object_id) + ": component";
            auto id = threemf_index(x, "objectid", where);
            if (!id) return id.error();
            auto m = threemf_parse_transform(x, where);
            if (!m) return m.error();
            object->components.push_back({*id, *m});
        } else if (tag == "build") {
            in_build = true;
        } else if (in_build && tag == "item") {
            const std::string where = "build item " + std::to_string(model.items.size());
            auto id = threemf_index(x, "objectid", where);
            if (!id) return id.error();
            auto m = threemf_parse_transform(x, where);
            if (!m) return m.error();
            model.items.push_back({*id, *m});
        }
    }
    if (!root) return fail(errc::parse_error, name + ": no <model> element");
    return model;
}

/// Appends object `id` under transform `m` (its components recursively, at most 32 deep, a
/// cycle refused); the soup may hold at most `max_points` points and as many triangles.
inline result<void> threemf_instantiate(const threemf_model& model, std::uint64_t id, const threemf_transform& m,
                                        polygon_soup& soup, std::vector<std::uint64_t>& path, std::uint64_t max_points,
                                        const std::string& name) {
    const auto it = model.by_id.find(id);
    if (it == model.by_id.end())
        return fail(errc::parse_error,
                    name + ": a build item or component names object " + std::to_string(id) + ", which does not exist");
    for (auto p : path)
        if (p == id) return fail(errc::parse_error, name + ": object " + std::to_string(id) + " contains itself");
    if (path.size() >= 32) return fail(errc::parse_error, name + ": components nested deeper than 32");
    const auto& o = model.objects[it->second];
    if (o.vertices.size() > max_points - std::min(max_points, soup.points.size()) ||
        o.triangles.size() > max_points - std::min<std::uint64_t>(max_points, soup.face_count()))
        return fail(errc::parse_error, name + ": the build instantiates more than " + std::to_string(max_points) +
                                           " points or triangles, over the input limit (refused)");
    const std::size_t base = soup.points.size();
    for (const auto& p : o.vertices) {
        std::array<double, 3> q;
        for (int c = 0; c < 3; ++c)
            q[static_cast<std::size_t>(c)] =
                p[0] * m[static_cast<std::size_t>(c)] + p[1] * m[3 + static_cast<std::size_t>(c)] +
                p[2] * m[6 + static_cast<std::size_t>(c)] + m[9 + static_cast<std::size_t>(c)];
        if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
            return fail(errc::parse_error,
                        name + ": object " + std::to_string(id) + " transformed overflows to infinity");
        soup.points.push_back(q);
    }
    soup.indices.reserve(soup.indices.size() + 3 * o.triangles.size());
    soup.face_offsets.reserve(soup.face_offsets.size() + o.triangles.size());
    for (const auto& t : o.triangles) {
        for (auto v : t) soup.indices.push_back(static_cast<std::uint32_t>(base + v));
        soup.face_offsets.push_back(soup.indices.size());
    }
    path.push_back(id);
    for (const auto& c : o.components)
        if (auto ok = threemf_instantiate(model, c.object, compose(c.transform, m), soup, path, max_points, name); !ok)
            return ok;
    path.pop_back();
    return {};
}

/// The 3D model part for the mesh's triangles (faces triangulated by `plan`).
template <class M, class T>
std::string threemf_model_text(const M& mesh, const stl_triangles<M, T>& plan) {
    const auto number = dense_vertex_numbers<M, T>(mesh);
    std::string out =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model unit=\"millimeter\" xml:lang=\"en-US\" "
        "xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n <resources>\n"
        "  <object id=\"1\" type=\"model\">\n   <mesh>\n    <vertices>\n";
    for (auto v : T::vertices(mesh)) {
        const auto p = T::position(mesh, v);
        out += "     <vertex x=\"";
        append_number(out, p[0]);
        out += "\" y=\"";
        append_number(out, p[1]);
        out += "\" z=\"";
        append_number(out, p[2]);
        out += "\"/>\n";
    }
    out += "    </vertices>\n    <triangles>\n";
    auto put = [&](auto a, auto b, auto c) {
        out += "     <triangle v1=\"";
        append_number(out, number[T::vertex_index(mesh, a)]);
        out += "\" v2=\"";
        append_number(out, number[T::vertex_index(mesh, b)]);
        out += "\" v3=\"";
        append_number(out, number[T::vertex_index(mesh, c)]);
        out += "\"/>\n";
    };
    std::size_t planned_face = 0, next_triangle = 0;
    for (auto f : T::faces(mesh)) {
        typename T::vertex_handle tri[3];
        std::size_t k = 0;
        bool plain = !has_inner_rings<M, T>(mesh, f);
        if (plain)
            for (auto v : T::face_vertices(mesh, f)) {
                if (k == 3) {
                    plain = false;
                    break;
                }
                tri[k++] = v;
            }
        if (plain && k == 3) {
            put(tri[0], tri[1], tri[2]);
        } else {
            // The plan lists the faces that are not plain triangles in this same order.
            const std::size_t end = next_triangle + plan.counts[planned_face++];
            for (; next_triangle < end; ++next_triangle) {
                const auto& t = plan.triangles[next_triangle];
                put(t[0], t[1], t[2]);
            }
        }
    }
    out +=
        "    </triangles>\n   </mesh>\n  </object>\n </resources>\n <build>\n  <item objectid=\"1\"/>\n "
        "</build>\n</model>\n";
    return out;
}

inline std::string threemf_package(std::string_view model) {
    static constexpr std::string_view types =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Types "
        "xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\"><Default Extension=\"rels\" "
        "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/><Default Extension=\"model\" "
        "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>\n";
    static constexpr std::string_view rels =
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships "
        "xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\"><Relationship "
        "Target=\"/3D/3dmodel.model\" Id=\"rel0\" "
        "Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>\n";
    return zip_archive({{"[Content_Types].xml", types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model}});
}

}  // namespace hmira::io::detail
