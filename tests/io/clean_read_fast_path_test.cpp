// tests/io/clean_read_fast_path_test.cpp
// Reading a file that needs no repair into halfedge_mesh skips repair_polygon_soup and builds
// the mesh in one pass (assign_polygons). That shortcut must be invisible: on random soups,
// clean ones and ones with each defect the repair handles, build_from_soup must give exactly
// what the repair path (detail::build_with_repair, add_face of every repaired face) gives:
// the same numbering of every element, the same links, positions, properties and report, or
// the same error with the mesh unchanged.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "io/io_support.hpp"
#include "support/checks.hpp"

namespace {

using hmira::halfedge_mesh;
using hmira::io::polygon_soup;
using T = hmira::default_traits<halfedge_mesh>;

/// A strip of a rows x cols grid (triangles and quads mixed), optionally closed into a torus,
/// with shuffled vertex numbers, face order and first corners, and isolated extra vertices.
polygon_soup random_surface(std::mt19937& rng, bool torus) {
    const int rows = 3 + static_cast<int>(rng() % 4), cols = 3 + static_cast<int>(rng() % 5);
    const int nrow = torus ? rows : rows + 1, ncol = torus ? cols : cols + 1;
    const std::size_t nv = static_cast<std::size_t>(nrow * ncol), extra = rng() % 3;
    std::vector<std::uint32_t> perm(nv + extra);
    std::iota(perm.begin(), perm.end(), 0u);
    std::shuffle(perm.begin(), perm.end(), rng);
    auto id = [&](int r, int c) { return perm[static_cast<std::size_t>((r % nrow) * ncol + (c % ncol))]; };
    std::vector<std::vector<std::uint32_t>> faces;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) {
            const auto a = id(r, c), b = id(r, c + 1), d = id(r + 1, c + 1), e = id(r + 1, c);
            if (rng() % 2)
                faces.push_back({a, b, d, e});
            else
                faces.push_back({a, b, d}), faces.push_back({a, d, e});
        }
    std::shuffle(faces.begin(), faces.end(), rng);
    for (auto& f : faces) std::rotate(f.begin(), f.begin() + static_cast<std::ptrdiff_t>(rng() % f.size()), f.end());
    polygon_soup s;
    std::uniform_real_distribution<double> u(-1, 1);
    for (std::size_t v = 0; v < nv + extra; ++v) s.points.push_back({u(rng), u(rng), u(rng)});
    for (const auto& f : faces) {
        s.indices.insert(s.indices.end(), f.begin(), f.end());
        s.face_offsets.push_back(s.indices.size());
    }
    return s;
}

std::vector<std::vector<std::uint32_t>> faces_of(const polygon_soup& s) {
    std::vector<std::vector<std::uint32_t>> out;
    for (std::size_t f = 0; f < s.face_count(); ++f)
        out.emplace_back(s.indices.begin() + static_cast<std::ptrdiff_t>(s.face_offsets[f]),
                         s.indices.begin() + static_cast<std::ptrdiff_t>(s.face_offsets[f + 1]));
    return out;
}

void set_faces(polygon_soup& s, const std::vector<std::vector<std::uint32_t>>& faces) {
    s.indices.clear();
    s.face_offsets.assign(1, 0);
    for (const auto& f : faces) {
        s.indices.insert(s.indices.end(), f.begin(), f.end());
        s.face_offsets.push_back(s.indices.size());
    }
}

enum class defect {
    none,
    holes,
    duplicate_face,
    flipped_face,
    degenerate_face,
    repeated_corner,
    third_face,
    pinched_vertex,
    duplicated_position,
    count
};

/// Damages the soup in one of the ways repair_polygon_soup handles (or leaves it alone).
void damage(polygon_soup& s, defect d, std::mt19937& rng) {
    auto faces = faces_of(s);
    auto pick = [&] { return static_cast<std::size_t>(rng() % faces.size()); };
    const auto nv = static_cast<std::uint32_t>(s.points.size());
    switch (d) {
        case defect::none: break;
        case defect::holes:  // boundaries, and sometimes a vertex with two fans
            for (int i = 0; i < 3 && faces.size() > 1; ++i)
                faces.erase(faces.begin() + static_cast<std::ptrdiff_t>(pick()));
            break;
        case defect::duplicate_face:
            faces.insert(faces.begin() + static_cast<std::ptrdiff_t>(pick()), faces[pick()]);
            break;
        case defect::flipped_face: {
            auto& f = faces[pick()];
            std::reverse(f.begin(), f.end());
            break;
        }
        case defect::degenerate_face: faces.push_back({faces[0][0], faces[0][1]}); break;
        case defect::repeated_corner: {
            auto& f = faces[pick()];
            f.insert(f.begin() + 1, f[1]);
            break;
        }
        case defect::third_face: {  // a new vertex on a fin over an existing edge
            const auto& f = faces[pick()];
            s.points.push_back({2, 2, 2});
            faces.push_back({f[1], f[0], nv});
            break;
        }
        case defect::pinched_vertex: {  // a separate triangle touching one vertex
            const auto v = faces[pick()][0];
            s.points.push_back({3, 0, 0});
            s.points.push_back({0, 3, 0});
            faces.insert(faces.begin() + static_cast<std::ptrdiff_t>(pick()), {v, nv, nv + 1});
            break;
        }
        case defect::duplicated_position:  // repair does not weld: positions play no part
            s.points[rng() % s.points.size()] = s.points[rng() % s.points.size()];
            break;
        case defect::count: break;
    }
    set_faces(s, faces);
}

/// The whole observable state of a halfedge_mesh, element by element, for exact comparison.
struct mesh_state {
    std::vector<std::array<double, 3>> positions;
    std::vector<std::uint32_t> vertex_halfedge, face_halfedge;
    std::vector<std::array<std::uint32_t, 4>> halfedges;  // target, face, next, prev
    std::vector<std::array<float, 3>> normals;
    std::vector<int> vertex_tags, edge_tags, halfedge_tags, face_tags;
    std::size_t vertices = 0, edges = 0, faces = 0;
    bool operator==(const mesh_state&) const = default;
};

mesh_state state_of(const halfedge_mesh& m) {
    mesh_state s;
    s.vertices = m.vertex_count(), s.edges = m.edge_count(), s.faces = m.face_count();
    for (std::size_t v = 0; v < m.vertex_index_bound(); ++v) {
        const hmira::vertex_handle vh(static_cast<std::uint32_t>(v));
        const auto& p = m.position(vh);
        s.positions.push_back({p[0], p[1], p[2]});
        s.vertex_halfedge.push_back(m.vertex_halfedge(vh).index);
    }
    for (std::size_t f = 0; f < m.face_index_bound(); ++f)
        s.face_halfedge.push_back(m.face_halfedge(hmira::face_handle(static_cast<std::uint32_t>(f))).index);
    for (std::size_t h = 0; h < m.halfedge_index_bound(); ++h) {
        const hmira::halfedge_handle hh(static_cast<std::uint32_t>(h));
        s.halfedges.push_back({m.target(hh).index, m.face(hh).index, m.next(hh).index, m.prev(hh).index});
    }
    if (auto p = m.get_vertex_property<hmira::vec3<float>>("v:normal"))
        for (const auto& n : p->values()) s.normals.push_back({n[0], n[1], n[2]});
    if (auto p = m.get_vertex_property<int>("tag")) s.vertex_tags.assign(p->values().begin(), p->values().end());
    if (auto p = m.get_edge_property<int>("tag")) s.edge_tags.assign(p->values().begin(), p->values().end());
    if (auto p = m.get_halfedge_property<int>("tag")) s.halfedge_tags.assign(p->values().begin(), p->values().end());
    if (auto p = m.get_face_property<int>("tag")) s.face_tags.assign(p->values().begin(), p->values().end());
    return s;
}

/// A mesh with earlier content and user properties, which a read must empty and keep.
halfedge_mesh used_mesh() {
    halfedge_mesh m;
    const auto a = m.add_vertex({0, 0, 0}), b = m.add_vertex({1, 0, 0}), c = m.add_vertex({0, 1, 0});
    EXPECT_TRUE(m.add_face({a, b, c}));
    m.add_vertex_property<int>("tag", 7)[a] = 1;
    m.add_edge_property<int>("tag", 8);
    m.add_halfedge_property<int>("tag", 9);
    m.add_face_property<int>("tag", 10);
    return m;
}

// A file's unused vertices stay (isolated), and random positions may make a face flat.
const hmira::validate_options unused_vertices_allowed{.relaxed = true, .check_geometry = false, .max_problems = 10};

std::string report_text(const hmira::io::read_report& r) {
    std::ostringstream s;
    s << r.repair.summary() << " | nm edges " << r.repair.nonmanifold_edges << " | dropped " << r.repair.dropped_faces
      << " | file vertices " << r.file_vertices << " | normals " << r.attributes.normals.size() << " | copied";
    for (auto v : r.copied_from) s << ' ' << v;
    s << " | sources";
    for (auto f : r.face_source) s << ' ' << f;
    return s.str();
}

}  // namespace

TEST(clean_read_fast_path, gives_the_repair_paths_mesh_report_and_errors_on_random_soups) {
    std::mt19937 rng(20);
    std::size_t fast = 0, repaired = 0;
    for (int round = 0; round < 1500; ++round) {
        const auto d = static_cast<defect>(round % static_cast<int>(defect::count));
        auto soup = random_surface(rng, rng() % 2 == 0);
        damage(soup, d, rng);
        if (rng() % 3 == 0)
            for (std::size_t v = 0; v < soup.points.size(); ++v)
                soup.attributes.normals.push_back({static_cast<float>(v), 0.5f, -1.0f});
        const hmira::io::read_options options{.repair = rng() % 4 != 0};
        SCOPED_TRACE(::testing::Message()
                     << "round " << round << ", defect " << static_cast<int>(d) << ", repair " << options.repair);

        // Whether the one-pass build takes this soup (the fast path), to check that both paths
        // are exercised.
        halfedge_mesh probe;
        const bool bulk = static_cast<bool>(probe.assign_polygons(std::span<const std::array<double, 3>>(soup.points),
                                                                  std::span<const std::uint64_t>(soup.face_offsets),
                                                                  std::span<const std::uint32_t>(soup.indices)));
        (bulk ? fast : repaired) += 1;

        auto new_mesh = used_mesh(), old_mesh = used_mesh();
        const auto before = state_of(new_mesh);
        auto soup_copy = soup;
        const auto got = hmira::io::build_from_soup<halfedge_mesh>(new_mesh, std::move(soup), "f.ply", options);
        const auto want =
            hmira::io::detail::build_with_repair<halfedge_mesh>(old_mesh, std::move(soup_copy), "f.ply", options);
        ASSERT_EQ(got.has_value(), want.has_value());
        if (!want) {
            EXPECT_EQ(got.error().code, want.error().code);
            EXPECT_EQ(got.error().message, want.error().message);
            EXPECT_EQ(got.error().element, want.error().element);
            EXPECT_TRUE(state_of(new_mesh) == before) << "a refused read changed the mesh";
            continue;
        }
        if (bulk) {
            EXPECT_TRUE(want->repair.clean())
                << "the fast path took a soup that repair changes: " << want->repair.summary();
        }
        EXPECT_EQ(report_text(*got), report_text(*want));
        EXPECT_TRUE(state_of(new_mesh) == state_of(old_mesh)) << "the fast path built a different mesh";
        EXPECT_TRUE(hmira_test::is_valid(new_mesh, unused_vertices_allowed));
        EXPECT_EQ(new_mesh.vertex_count() - new_mesh.edge_count() + new_mesh.face_count(),
                  old_mesh.vertex_count() - old_mesh.edge_count() + old_mesh.face_count());
        // The user's properties were kept, emptied to their defaults.
        const auto tags = new_mesh.get_vertex_property<int>("tag");
        ASSERT_TRUE(tags.has_value());
        EXPECT_TRUE(std::all_of(tags->values().begin(), tags->values().end(), [](int t) { return t == 7; }));
        EXPECT_GT(new_mesh.change_count(), 0u);
    }
    EXPECT_GT(fast, 300u);
    EXPECT_GT(repaired, 300u);
}

TEST(clean_read_fast_path, a_clean_file_reads_the_same_through_read_mesh) {
    std::mt19937 rng(7);
    auto soup = random_surface(rng, true);
    hmira_test::scratch_dir dir;
    std::ostringstream off;
    off << "OFF\n" << soup.points.size() << ' ' << soup.face_count() << " 0\n";
    off.precision(17);
    for (const auto& p : soup.points) off << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    for (std::size_t f = 0; f < soup.face_count(); ++f) {
        off << soup.face_offsets[f + 1] - soup.face_offsets[f];
        for (auto k = soup.face_offsets[f]; k < soup.face_offsets[f + 1]; ++k) off << ' ' << soup.indices[k];
        off << '\n';
    }
    hmira_test::write_bytes(dir / "t.off", off.str());
    halfedge_mesh read, built;
    const auto r = hmira::io::read_mesh(read, dir / "t.off");
    ASSERT_TRUE(r) << r.error().message;
    EXPECT_TRUE(r->repair.clean());
    auto parsed = hmira::io::read_soup(dir / "t.off");
    ASSERT_TRUE(parsed);
    ASSERT_TRUE(hmira::io::detail::build_with_repair<halfedge_mesh>(built, std::move(*parsed), "t.off"));
    EXPECT_TRUE(state_of(read) == state_of(built));
    EXPECT_TRUE(hmira_test::is_valid(read, unused_vertices_allowed));
}

namespace {

/// The soup as a PLY file (ASCII, or binary through write_mesh of a face_vertex_mesh when the
/// soup is one that model holds), normals included when the soup has them.
std::string ascii_ply(const polygon_soup& s) {
    std::ostringstream o;
    o.precision(17);
    const bool normals = !s.attributes.normals.empty();
    o << "ply\nformat ascii 1.0\nelement vertex " << s.points.size()
      << "\nproperty double x\nproperty double y\nproperty double z\n";
    if (normals) o << "property float nx\nproperty float ny\nproperty float nz\n";
    o << "element face " << s.face_count() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (std::size_t v = 0; v < s.points.size(); ++v) {
        o << s.points[v][0] << ' ' << s.points[v][1] << ' ' << s.points[v][2];
        if (normals)
            o << ' ' << s.attributes.normals[v][0] << ' ' << s.attributes.normals[v][1] << ' '
              << s.attributes.normals[v][2];
        o << '\n';
    }
    for (std::size_t f = 0; f < s.face_count(); ++f) {
        o << s.face_offsets[f + 1] - s.face_offsets[f];
        for (auto k = s.face_offsets[f]; k < s.face_offsets[f + 1]; ++k) o << ' ' << s.indices[k];
        o << '\n';
    }
    return o.str();
}

}  // namespace

TEST(clean_read_fast_path, ply_files_read_as_through_the_repair_path_clean_or_not) {
    std::mt19937 rng(2026);
    hmira_test::scratch_dir dir;
    std::size_t clean = 0;
    for (int round = 0; round < 200; ++round) {
        const auto d = static_cast<defect>(round % static_cast<int>(defect::count));
        auto soup = random_surface(rng, rng() % 2 == 0);
        damage(soup, d, rng);
        if (rng() % 2)
            for (std::size_t v = 0; v < soup.points.size(); ++v)
                soup.attributes.normals.push_back({0.25f, static_cast<float>(v), 1.0f});
        const hmira::io::read_options options{.repair = rng() % 4 != 0};
        SCOPED_TRACE(::testing::Message()
                     << "round " << round << ", defect " << static_cast<int>(d) << ", repair " << options.repair);
        const auto file = dir / "r.ply";
        hmira_test::write_bytes(file, ascii_ply(soup));
        auto read = used_mesh(), built = used_mesh();
        const auto before = state_of(read);
        const auto got = hmira::io::read_mesh(read, file, options);
        auto parsed = hmira::io::read_soup(file);
        if (!parsed) {  // the parser's own refusals (a face of 2 corners) come first, either way
            ASSERT_FALSE(got);
            EXPECT_EQ(got.error().message, parsed.error().message);
            EXPECT_TRUE(state_of(read) == before) << "a refused read changed the mesh";
            continue;
        }
        const auto want =
            hmira::io::detail::build_with_repair<halfedge_mesh>(built, std::move(*parsed), file.string(), options);
        ASSERT_EQ(got.has_value(), want.has_value());
        if (!want) {
            EXPECT_EQ(got.error().code, want.error().code);
            EXPECT_EQ(got.error().message, want.error().message);
            EXPECT_TRUE(state_of(read) == before) << "a refused read changed the mesh";
            continue;
        }
        clean += want->repair.clean();
        EXPECT_EQ(got->format, "ply (ascii)");
        EXPECT_EQ(report_text(*got), report_text(*want));
        EXPECT_TRUE(state_of(read) == state_of(built)) << "the PLY fast path built a different mesh";
        EXPECT_TRUE(hmira_test::is_valid(read, unused_vertices_allowed));
    }
    EXPECT_GT(clean, 40u);
}
