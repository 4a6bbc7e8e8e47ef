// halfedge_mesh reuses the slots of deleted elements: an Euler operator followed by its inverse
// allocates nothing and leaves the index bounds as they were; a versioned handle detects that
// its element is gone even after the slot is reused; a reused slot's properties start at their
// defaults; with reuse off, new elements append; garbage collection still works afterwards.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <set>
#include <cstdlib>
#include <new>
#include <random>
#include <string>
#include <vector>

#include <hmira/algorithms/euler/make_edge_face.hpp>
#include <hmira/algorithms/euler/make_edge_vertex.hpp>
#include <hmira/algorithms/euler/make_vertex.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/checks.hpp"
#include "support/shapes.hpp"

// Counts every allocation of the test binary, so that a test can prove a stretch of code made
// none (std::vector growth, std::string, anything through operator new). The helpers stay out
// of line: g++ would otherwise pair the inlined operator new with std::free and warn.
namespace {
std::atomic<std::size_t> allocations{0};
[[gnu::noinline]] void* counted_allocate(std::size_t n) {
    ++allocations;
    if (void* p = std::malloc(n ? n : 1)) return p;
    throw std::bad_alloc();
}
[[gnu::noinline]] void release(void* p) noexcept { std::free(p); }
}  // namespace
void* operator new(std::size_t n) { return counted_allocate(n); }
void* operator new[](std::size_t n) { return counted_allocate(n); }
void operator delete(void* p) noexcept { release(p); }
void operator delete(void* p, std::size_t) noexcept { release(p); }
void operator delete[](void* p) noexcept { release(p); }
void operator delete[](void* p, std::size_t) noexcept { release(p); }

namespace {

using namespace hmira;

struct bounds {
    std::size_t v, e, f, free_v, free_e, free_f;
    bool operator==(const bounds&) const = default;
};
bounds bounds_of(const halfedge_mesh& m) {
    return {m.vertex_index_bound(), m.edge_index_bound(), m.face_index_bound(),
            m.free_vertex_slots(),  m.free_edge_slots(),  m.free_face_slots()};
}

halfedge_mesh quad_grid(std::size_t n) {
    halfedge_mesh m;
    EXPECT_TRUE(hmira_test::add_face_list(m, hmira_test::grid(n, n)));
    return m;
}

// The diagonal corners of face f: h0 and next(next(h0)).
std::pair<halfedge_handle, halfedge_handle> diagonal(const halfedge_mesh& m, face_handle f) {
    const auto h0 = m.face_halfedge(f);
    return {h0, m.next(m.next(h0))};
}

TEST(slot_reuse, operator_then_inverse_allocates_nothing_and_keeps_the_bounds) {
    auto m = quad_grid(8);
    const auto faces_before = hmira_test::canonical_faces(m);
    std::vector<face_handle> faces(m.faces().begin(), m.faces().end());
    std::vector<halfedge_handle> halfedges(m.halfedges().begin(), m.halfedges().end());
    // One pair of each kind first: the first deletion of a kind gives the free list its slot.
    {
        const auto [h0, h1] = diagonal(m, faces[0]);
        const auto r = make_edge_face(m, h0, h1);
        ASSERT_TRUE(r);
        ASSERT_TRUE(kill_edge_face(m, r->halfedge));
        const auto s = make_edge_vertex(m, halfedges[0], {0.5, 0.5, 0});
        ASSERT_TRUE(s);
        ASSERT_TRUE(kill_edge_vertex(m, s->halfedge));
    }
    {  // the counter sees an allocation, so a zero below means something
        const auto a0 = allocations.load();
        std::vector<int> probe(10);
        EXPECT_GT(allocations.load(), a0);
    }
    const auto start = bounds_of(m);
    EXPECT_EQ(start.free_e, 1u);  // makeEV took the edge slot killEF had freed
    EXPECT_EQ(start.free_f, 1u);
    EXPECT_EQ(start.free_v, 1u);
    std::mt19937 rng(20);
    for (int step = 0; step < 600; ++step) {
        const auto kind = rng() % 3;
        const auto before = allocations.load();
        bool ok = false;
        if (kind == 0) {  // makeEF then killEF on a random face's diagonal
            const auto [h0, h1] = diagonal(m, faces[rng() % faces.size()]);
            const auto r = make_edge_face(m, h0, h1);
            const bool split = r && m.face_count() == faces.size() + 1;
            ok = r && split && kill_edge_face(m, r->halfedge);
        } else if (kind == 1) {  // makeEV then killEV at a random corner
            const auto r = make_edge_vertex(m, halfedges[rng() % halfedges.size()], {0.25, 0.25, 1});
            ok = r && kill_edge_vertex(m, r->halfedge);
        } else {  // makeV then killV
            const auto r = make_vertex(m, {3, 3, 3});
            ok = kill_vertex(m, r.vertex).has_value();
        }
        const auto made = allocations.load() - before;
        ASSERT_TRUE(ok) << "step " << step;
        ASSERT_EQ(made, 0u) << "step " << step << " (kind " << kind << ") allocated";
        ASSERT_EQ(bounds_of(m), start) << "step " << step;
        ASSERT_TRUE(hmira_test::is_valid(m, {.relaxed = true})) << "step " << step;
    }
    EXPECT_EQ(hmira_test::canonical_faces(m), faces_before);
}

TEST(slot_reuse, a_pass_of_operators_then_a_pass_of_inverses_reuses_every_slot) {
    // One pass of makeEF over every face, one pass of killEF, twice: the second makeEF pass
    // finds all its slots on the free lists, so the bounds after it equal those after the first.
    auto m = quad_grid(6);
    const auto faces_before = hmira_test::canonical_faces(m);
    std::vector<face_handle> faces(m.faces().begin(), m.faces().end());
    std::vector<bounds> after_make;
    for (int round = 0; round < 2; ++round) {
        std::vector<halfedge_handle> made;
        for (auto f : faces) {
            const auto [h0, h1] = diagonal(m, f);
            const auto r = make_edge_face(m, h0, h1);
            ASSERT_TRUE(r);
            made.push_back(r->halfedge);
            ASSERT_TRUE(hmira_test::is_valid(m, {.relaxed = true}));
        }
        after_make.push_back(bounds_of(m));
        for (auto h : made) {
            ASSERT_TRUE(kill_edge_face(m, h));
            ASSERT_TRUE(hmira_test::is_valid(m, {.relaxed = true}));
        }
        EXPECT_EQ(hmira_test::canonical_faces(m), faces_before);
    }
    EXPECT_EQ(after_make[1].v, after_make[0].v);
    EXPECT_EQ(after_make[1].e, after_make[0].e);
    EXPECT_EQ(after_make[1].f, after_make[0].f);
    EXPECT_EQ(after_make[0].e, 2 * 6 * 7 + faces.size());  // the first pass appended one edge per face
}

TEST(slot_reuse, versioned_handles_detect_deleted_and_reused_slots) {
    auto m = quad_grid(2);
    const auto f = *m.faces().begin();
    const auto [h0, h1] = diagonal(m, f);
    const auto r = make_edge_face(m, h0, h1);
    ASSERT_TRUE(r);
    const auto vh = m.versioned(r->halfedge);
    const auto ve = m.versioned(halfedge_mesh::edge(r->halfedge));
    const auto vf = m.versioned(r->face);
    EXPECT_TRUE(m.is_valid(vh) && m.is_valid(ve) && m.is_valid(vf));
    ASSERT_TRUE(kill_edge_face(m, r->halfedge));
    // Deleted, slot not yet reused: both kinds of handle are invalid.
    EXPECT_FALSE(m.is_valid(r->halfedge));
    EXPECT_FALSE(m.is_valid(vh));
    EXPECT_FALSE(m.is_valid(ve));
    // The same operator again takes the same slots: the plain handle now names the new edge,
    // the versioned one knows its edge is gone.
    const auto again = make_edge_face(m, h0, h1);
    ASSERT_TRUE(again);
    EXPECT_EQ(again->halfedge.index >> 1, r->halfedge.index >> 1) << "the freed edge slot is reused";
    EXPECT_TRUE(m.is_valid(r->halfedge));
    EXPECT_FALSE(m.is_valid(vh));
    EXPECT_FALSE(m.is_valid(ve));
    EXPECT_EQ(m.generation(again->halfedge), vh.generation + 1);
    EXPECT_TRUE(m.is_valid(m.versioned(again->halfedge)));
    // kill_edge_face removed the new face; its slot came back with a new generation.
    EXPECT_EQ(again->face, r->face);
    EXPECT_FALSE(m.is_valid(vf));
    EXPECT_EQ(m.generation(again->face), 1u);
    EXPECT_TRUE(m.is_valid(f));

    // Vertices: erased and re-added.
    const auto v = m.add_vertex({7, 7, 7});
    const auto vv = m.versioned(v);
    m.erase_vertex(v);
    EXPECT_FALSE(m.is_valid(vv));
    const auto w = m.add_vertex({8, 8, 8});
    EXPECT_EQ(w, v);
    EXPECT_TRUE(m.is_valid(v));
    EXPECT_FALSE(m.is_valid(vv));
    EXPECT_EQ(m.position(w), (vec3<double>{8, 8, 8}));
    EXPECT_TRUE(m.is_isolated(w));
    EXPECT_TRUE(hmira_test::is_valid(m, {.relaxed = true}));
    // Out of range is invalid too.
    EXPECT_FALSE(m.is_valid(versioned_handle<vertex_tag>{vertex_handle(999u), 0}));
}

TEST(slot_reuse, reused_slots_start_with_default_property_values) {
    auto m = quad_grid(2);
    auto vp = m.add_vertex_property<std::string>("name", "fresh");
    auto ep = m.add_edge_property<int>("e", -1);
    auto hp = m.add_halfedge_property<double>("h", 0.5);
    auto fp = m.add_face_property<int>("f", 42);
    const auto f = *m.faces().begin();
    const auto [h0, h1] = diagonal(m, f);
    auto r = make_edge_face(m, h0, h1);
    ASSERT_TRUE(r);
    ep[halfedge_mesh::edge(r->halfedge)] = 7;
    hp[r->halfedge] = 9.0;
    hp[halfedge_mesh::opposite(r->halfedge)] = 10.0;
    fp[r->face] = 1;
    fp[f] = 2;
    ASSERT_TRUE(kill_edge_face(m, r->halfedge));
    r = make_edge_face(m, h0, h1);
    ASSERT_TRUE(r);
    EXPECT_EQ(ep[halfedge_mesh::edge(r->halfedge)], -1);
    EXPECT_EQ(hp[r->halfedge], 0.5);
    EXPECT_EQ(hp[halfedge_mesh::opposite(r->halfedge)], 0.5);
    EXPECT_EQ(fp[r->face], 42) << "the new face took the freed face's slot";
    EXPECT_EQ(fp[f], 2) << "the surviving face keeps its value";

    const auto v = m.add_vertex({5, 5, 5});
    vp[v] = "used";
    m.erase_vertex(v);
    const auto w = m.add_vertex({6, 6, 6});
    ASSERT_EQ(w, v);
    EXPECT_EQ(vp[w], "fresh");
}

TEST(slot_reuse, with_reuse_off_new_elements_append_in_creation_order) {
    auto m = quad_grid(2);
    m.set_slot_reuse(false);
    const auto a = m.add_vertex({5, 5, 5});
    m.erase_vertex(a);
    const auto b = m.add_vertex({6, 6, 6});
    EXPECT_EQ(b.index, a.index + 1);
    EXPECT_EQ(m.free_vertex_slots(), 1u) << "the slot still waits";
    m.set_slot_reuse(true);
    EXPECT_EQ(m.add_vertex({7, 7, 7}), a);
    EXPECT_EQ(m.free_vertex_slots(), 0u);
    // clear_elements (what reading a file uses) keeps the setting.
    m.set_slot_reuse(false);
    m.clear_elements();
    EXPECT_FALSE(m.slot_reuse());
}

TEST(slot_reuse, collect_garbage_after_reuse_keeps_the_surface_and_empties_the_free_lists) {
    auto m = quad_grid(5);
    std::vector<face_handle> faces(m.faces().begin(), m.faces().end());
    std::mt19937 rng(7);
    std::vector<halfedge_handle> kept;  // diagonals left in, so that garbage and live mix
    for (int step = 0; step < 200; ++step) {
        const auto f = faces[rng() % faces.size()];
        if (!m.is_valid(f) || std::ranges::distance(m.face_vertices(f)) != 4) continue;
        const auto [h0, h1] = diagonal(m, f);
        const auto r = make_edge_face(m, h0, h1);
        ASSERT_TRUE(r);
        if (rng() % 2)
            ASSERT_TRUE(kill_edge_face(m, r->halfedge));
        else
            kept.push_back(r->halfedge);
        const auto v = m.add_vertex({9, 9, 9});
        if (rng() % 2) m.erase_vertex(v);
        ASSERT_TRUE(hmira_test::is_valid(m, {.relaxed = true}));
    }
    const auto faces_before = hmira_test::canonical_faces(m);
    const auto counts = std::array{m.vertex_count(), m.edge_count(), m.face_count()};
    [[maybe_unused]] const auto map = m.collect_garbage();
    EXPECT_EQ(hmira_test::canonical_faces(m), faces_before);
    EXPECT_EQ((std::array{m.vertex_count(), m.edge_count(), m.face_count()}), counts);
    EXPECT_EQ(m.vertex_index_bound(), m.vertex_count());
    EXPECT_EQ(m.free_vertex_slots() + m.free_edge_slots() + m.free_face_slots(), 0u);
    EXPECT_TRUE(hmira_test::is_valid(m, {.relaxed = true}));
}

TEST(slot_reuse, a_copy_reuses_its_own_slots_without_allocating) {
    auto m = quad_grid(3);
    const auto f = *m.faces().begin();
    const auto [h0, h1] = diagonal(m, f);
    auto r = make_edge_face(m, h0, h1);
    ASSERT_TRUE(r);
    ASSERT_TRUE(kill_edge_face(m, r->halfedge));
    halfedge_mesh copy = m;
    const auto start = bounds_of(copy);
    const auto before = allocations.load();
    for (int i = 0; i < 10; ++i) {
        auto s = make_edge_face(copy, h0, h1);
        ASSERT_TRUE(s);
        ASSERT_TRUE(kill_edge_face(copy, s->halfedge));
    }
    EXPECT_EQ(allocations.load(), before);
    EXPECT_EQ(bounds_of(copy), start);
    EXPECT_EQ(bounds_of(m), start) << "the original is untouched";
    EXPECT_TRUE(hmira_test::is_valid(copy, {.relaxed = true}));
}

// The free lists live in the deleted slots' own records (an edge's first next, a face's
// halfedge, a vertex's outgoing halfedge). reverse_orientation swaps every next with its prev,
// deleted edges' too, and must put the links back: else the second reuse below reads a stale
// prev as the list's next slot and hands out a live edge's slot (or one past the bound).
TEST(slot_reuse, freed_slots_survive_reversal_and_moves_and_are_taken_last_freed_first) {
    auto m = quad_grid(4);
    std::vector<face_handle> faces(m.faces().begin(), m.faces().end());
    std::vector<halfedge_handle> made;
    for (std::size_t i = 0; i < 6; ++i) {
        const auto [h0, h1] = diagonal(m, faces[2 * i]);
        const auto r = make_edge_face(m, h0, h1);
        ASSERT_TRUE(r);
        made.push_back(r->halfedge);
    }
    std::vector<std::uint32_t> freed;  // edge slots in the order they are freed
    for (auto h : made) {
        ASSERT_TRUE(kill_edge_face(m, h));
        freed.push_back(halfedge_mesh::edge(h).index);
    }
    const auto start = bounds_of(m);
    ASSERT_EQ(start.free_e, 6u);
    ASSERT_EQ(start.free_f, 6u);

    m.reverse_orientation();
    ASSERT_TRUE(hmira_test::is_valid(m, {.relaxed = true}));
    EXPECT_EQ(bounds_of(m), start);

    // A move leaves the source's lists empty (its records went with them).
    halfedge_mesh moved = std::move(m);
    EXPECT_EQ(moved.free_edge_slots(), 6u);
    EXPECT_EQ(m.free_edge_slots() + m.free_face_slots() + m.free_vertex_slots(), 0u);
    const auto fresh = m.add_vertex({1, 2, 3});
    EXPECT_EQ(fresh.index, 0u) << "a moved-from mesh appends";

    for (std::size_t i = 0; i < 6; ++i) {
        const auto [h0, h1] = diagonal(moved, faces[2 * i]);
        const auto r = make_edge_face(moved, h0, h1);
        ASSERT_TRUE(r) << "reuse " << i;
        EXPECT_EQ(halfedge_mesh::edge(r->halfedge).index, freed[freed.size() - 1 - i])
            << "reuse " << i << ": last freed first";
        ASSERT_TRUE(hmira_test::is_valid(moved, {.relaxed = true})) << "reuse " << i;
    }
    const auto end = bounds_of(moved);
    EXPECT_EQ(end.e, start.e) << "every edge came from the free list";
    EXPECT_EQ(end.f, start.f);
    EXPECT_EQ(end.free_e, 0u);
    EXPECT_EQ(end.free_f, 0u);
}

// Faces as loops of positions, each rotated to start at its smallest: compares two meshes'
// surfaces whatever their numbering.
std::multiset<std::vector<std::array<double, 3>>> faces_by_position(const halfedge_mesh& m) {
    std::multiset<std::vector<std::array<double, 3>>> out;
    for (auto f : m.faces()) {
        std::vector<std::array<double, 3>> loop;
        for (auto v : m.face_vertices(f)) loop.push_back({m.position(v).x, m.position(v).y, m.position(v).z});
        std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
        out.insert(loop);
    }
    return out;
}

TEST(slot_reuse, loop_subdivision_of_a_mesh_with_free_slots_matches_that_of_its_compacted_copy) {
    // Loop tells a level's new vertices by index; free slots below the bound must not fool it.
    halfedge_mesh m;
    ASSERT_TRUE(generate_octahedron(m));
    for (int i = 0; i < 3; ++i) {
        const auto r = make_edge_vertex(m, *m.halfedges().begin(), {9, 9, 9});
        ASSERT_TRUE(r);
        ASSERT_TRUE(kill_edge_vertex(m, r->halfedge));
        m.erase_vertex(m.add_vertex({8, 8, 8}));
    }
    ASSERT_GT(m.free_vertex_slots(), 0u);
    ASSERT_GT(m.free_edge_slots(), 0u);
    auto compact = m;
    [[maybe_unused]] const auto map = compact.collect_garbage();
    ASSERT_TRUE(loop_subdivide(m, {.levels = 2}));
    ASSERT_TRUE(loop_subdivide(compact, {.levels = 2}));
    EXPECT_TRUE(m.slot_reuse()) << "the setting comes back after the scheme";
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_EQ(m.face_count(), compact.face_count());
    EXPECT_EQ(faces_by_position(m), faces_by_position(compact));
}

}  // namespace
