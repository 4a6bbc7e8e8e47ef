// detail::trivial_array, the realloc-backed record array under halfedge_mesh's connectivity:
// it keeps its elements through every growth (realloc may move the block), copies are
// independent, moves leave the source empty, a refused allocation leaves the array unchanged,
// and a mesh built on it survives copy, growth, deletion and garbage collection intact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <new>
#include <random>
#include <vector>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/meshes/detail/trivial_array.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#include "support/checks.hpp"

// Under AddressSanitizer a refused allocation must come back as null (as from the C library)
// rather than abort the test, which checks what the array does then.
extern "C" const char* __asan_default_options() { return "allocator_may_return_null=1"; }

namespace {

struct record {
    std::uint32_t a = 7;
    std::uint64_t b = 9;
};

using hmira::detail::trivial_array;

// Mirrors every operation on a std::vector (the reference) and compares after each step.
TEST(TrivialArray, random_operations_match_std_vector) {
    std::mt19937 rng(12345);
    trivial_array<std::uint32_t> a;
    std::vector<std::uint32_t> ref;
    for (int step = 0; step < 20000; ++step) {
        const auto op = rng() % 100;
        if (op < 70) {
            const auto v = static_cast<std::uint32_t>(rng());
            a.push_back(v);
            ref.push_back(v);
        } else if (op < 80) {
            const std::size_t n = rng() % (ref.size() + 64);
            a.resize(n, 5u);
            ref.resize(n, 5u);
        } else if (op < 88) {
            const std::size_t n = rng() % (2 * ref.size() + 64);
            a.reserve(n);
            ASSERT_GE(a.capacity(), n);
        } else if (op < 90) {
            a.clear();
            ref.clear();
        } else if (op < 93) {
            const std::size_t n = rng() % 300;
            a.assign(n, 3u);
            ref.assign(n, 3u);
        } else if (op < 97 && !ref.empty()) {
            a.push_back(a[rng() % a.size()]);  // an element of the array itself, across a possible move
            ref.push_back(a[a.size() - 1]);
            ASSERT_EQ(ref.back(), a[a.size() - 1]);
        } else {
            trivial_array<std::uint32_t> copy(a);
            a = std::move(copy);
        }
        ASSERT_EQ(a.size(), ref.size());
        ASSERT_EQ(a.empty(), ref.empty());
        if (a.capacity() > 0) {
            ASSERT_EQ(reinterpret_cast<std::uintptr_t>(a.data()) % 64, 0u);
        }
    }
    ASSERT_EQ(std::vector<std::uint32_t>(a.begin(), a.end()), ref);
}

TEST(TrivialArray, push_back_of_own_element_survives_growth) {
    trivial_array<record> a;
    a.push_back({1, 2});
    for (int i = 0; i < 16; ++i) {  // capacity doubles each time: up to a million records
        while (a.size() < a.capacity()) a.push_back({3, 4});
        a.push_back(a[0]);  // grows, so a[0] moves while being read
        ASSERT_EQ(a[a.size() - 1].a, 1u);
        ASSERT_EQ(a[a.size() - 1].b, 2u);
    }
}

// realloc promises 16-byte alignment only; the array keeps its elements on a 64-byte boundary
// even when realloc hands back a block at another offset (forced here by growing two arrays in
// turn between other allocations of odd sizes), moving them there without losing one.
TEST(TrivialArray, elements_start_on_a_cache_line_through_every_reallocation) {
    struct odd {
        std::uint32_t a, b, c;
    };
    std::mt19937 rng(7);
    trivial_array<odd> x, y;
    std::vector<std::vector<char>> noise;
    for (std::uint32_t i = 0; i < 3000; ++i) {
        x.push_back({i, 2 * i, 3 * i});
        if (i % 3 == 0) y.reserve(y.capacity() + 1 + rng() % 5);
        y.push_back({i, i + 1, i + 2});
        if (rng() % 4 == 0) noise.emplace_back(1 + rng() % 200);
        ASSERT_EQ(reinterpret_cast<std::uintptr_t>(x.data()) % 64, 0u);
        ASSERT_EQ(reinterpret_cast<std::uintptr_t>(y.data()) % 64, 0u);
    }
    for (std::uint32_t i = 0; i < 3000; ++i) {
        ASSERT_EQ(x[i].a, i);
        ASSERT_EQ(x[i].b, 2 * i);
        ASSERT_EQ(x[i].c, 3 * i);
        ASSERT_EQ(y[i].a, i);
        ASSERT_EQ(y[i].c, i + 2);
    }
    const trivial_array<odd> copy(x);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(copy.data()) % 64, 0u);
    EXPECT_EQ(copy[2999].c, 3u * 2999);
}

TEST(TrivialArray, ensure_room_grows_geometrically_and_reserve_exactly) {
    trivial_array<std::uint32_t> a;
    for (std::uint32_t i = 0; i < 128; ++i) a.push_back(i);
    ASSERT_EQ(a.capacity(), 128u);  // 16, 32, 64, 128
    a.ensure_room(128);
    EXPECT_EQ(a.capacity(), 128u);
    a.ensure_room(130);
    EXPECT_EQ(a.capacity(), 256u);  // doubled, not 130: appends stay amortised O(1)
    a.reserve(1000);
    EXPECT_EQ(a.capacity(), 1000u);
    a.reserve(10);  // never shrinks
    EXPECT_EQ(a.capacity(), 1000u);
    for (std::uint32_t i = 0; i < 128; ++i) ASSERT_EQ(a[i], i);
}

TEST(TrivialArray, resize_fills_with_the_value_and_shrink_keeps_room) {
    trivial_array<record> a;
    a.resize(10);
    for (const auto& r : a) EXPECT_TRUE(r.a == 7 && r.b == 9);
    a.resize(20, record{1, 1});
    EXPECT_EQ(a[9].a, 7u);
    EXPECT_EQ(a[10].a, 1u);
    EXPECT_EQ(a[19].b, 1u);
    const auto room = a.capacity();
    a.resize(3);
    EXPECT_EQ(a.size(), 3u);
    EXPECT_EQ(a.capacity(), room);
    EXPECT_EQ(a[2].a, 7u);
}

TEST(TrivialArray, copies_are_independent_and_moves_empty_the_source) {
    trivial_array<std::uint32_t> a;
    for (std::uint32_t i = 0; i < 100; ++i) a.push_back(i);
    trivial_array<std::uint32_t> b(a);
    b[0] = 1000;
    EXPECT_EQ(a[0], 0u);
    EXPECT_EQ(b[99], 99u);
    trivial_array<std::uint32_t> c;
    c = a;
    c.push_back(5);
    EXPECT_EQ(a.size(), 100u);
    EXPECT_EQ(c.size(), 101u);
    trivial_array<std::uint32_t> d(std::move(c));
    EXPECT_EQ(d.size(), 101u);
    EXPECT_TRUE(c.empty());  // NOLINT(bugprone-use-after-move): moved-from is documented empty
    d = std::move(b);
    EXPECT_EQ(d[0], 1000u);
    EXPECT_EQ(d.size(), 100u);
    const trivial_array<std::uint32_t> empty;
    trivial_array<std::uint32_t> e(empty);
    EXPECT_TRUE(e.empty());
    EXPECT_EQ(e.data(), nullptr);
}

TEST(TrivialArray, refused_allocation_leaves_the_array_unchanged) {
    trivial_array<record> a;
    for (std::uint32_t i = 0; i < 50; ++i) a.push_back({i, i});
    const auto room = a.capacity();
    const auto* data = a.data();
    // More bytes than size_t holds, and more than any machine has: both refused, nothing changes.
    EXPECT_THROW(a.reserve(SIZE_MAX / 2), std::bad_alloc);
    EXPECT_THROW(a.resize(SIZE_MAX / sizeof(record) / 2), std::bad_alloc);
    EXPECT_THROW(a.assign(SIZE_MAX / 4, record{}), std::bad_alloc);
    EXPECT_EQ(a.size(), 50u);
    EXPECT_EQ(a.capacity(), room);
    EXPECT_EQ(a.data(), data);
    for (std::uint32_t i = 0; i < 50; ++i) ASSERT_EQ(a[i].a, i);
}

// The mesh on top: a copy taken before growth is untouched by it; growth after reserve, slot
// reuse and garbage collection keep the mesh valid and its counts exact.
TEST(TrivialArray, halfedge_mesh_copy_growth_and_collection_stay_valid) {
    hmira::halfedge_mesh m;
    ASSERT_TRUE(hmira::generate_icosahedron(m).has_value());
    const auto copy = m;
    m.reserve(1000, 3000, 2000);
    ASSERT_TRUE(hmira::loop_subdivide(m).has_value());
    EXPECT_EQ(m.vertex_count(), 42u);
    EXPECT_EQ(m.edge_count(), 120u);
    EXPECT_EQ(m.face_count(), 80u);
    EXPECT_EQ(copy.vertex_count(), 12u);
    EXPECT_EQ(copy.face_count(), 20u);
    EXPECT_TRUE(hmira_test::is_valid(copy));
    EXPECT_TRUE(hmira_test::is_valid(m));
    auto moved = std::move(m);
    EXPECT_TRUE(hmira_test::is_valid(moved));
    auto assigned = copy;
    assigned = moved;  // copy assignment over a mesh with storage of its own
    EXPECT_EQ(assigned.face_count(), 80u);
    EXPECT_TRUE(hmira_test::is_valid(assigned));
    // Raw erasure (nothing re-linked), then compaction: the other 78 faces keep their loops.
    auto expected = hmira_test::canonical_faces(moved);
    for (const auto f : {hmira::face_handle(3u), hmira::face_handle(7u)}) {
        std::vector<std::size_t> loop;
        for (auto v : moved.face_vertices(f)) loop.push_back(v.index);
        std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
        expected.erase(expected.find(loop));
        moved.erase_face(f);
    }
    [[maybe_unused]] const auto map = moved.collect_garbage();
    EXPECT_EQ(moved.face_count(), 78u);
    EXPECT_EQ(moved.face_index_bound(), 78u);
    EXPECT_EQ(assigned.face_count(), 80u);  // the copy kept its own records
    EXPECT_TRUE(hmira_test::is_valid(assigned));
    EXPECT_EQ(hmira_test::canonical_faces(moved), expected);
}

}  // namespace
