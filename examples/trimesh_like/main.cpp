// examples/trimesh_like/main.cpp
// docs/own-mesh.md, part 2: a Trimesh-style structure whose traits answer adjacency from its
// own arrays. The same generic code then runs three ways -- native arrays, hmira's indexed
// adapters, hmira's brute-force adapters -- and the program prints what each costs. It exits
// non-zero if the three disagree or a geometric check fails, so CI running it is a test.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <optional>
#include <vector>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/geometry/vertex_normals.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>

#include "trimesh.hpp"

namespace {

int failures = 0;

void check(bool ok, const char* what) {
    std::printf("  [%s] %s\n", ok ? " ok " : "FAIL", what);
    if (!ok) ++failures;
}

// [capabilities]
using lab::trimesh;
static_assert(hmira::vertex_adjacency_mesh<trimesh>, "neighbors");
static_assert(hmira::vertex_face_adjacency_mesh<trimesh>, "adjacentfaces");
static_assert(hmira::face_adjacency_mesh<trimesh>, "across_edge");
static_assert(hmira::mesh_builder<trimesh> && !hmira::polygon_mesh_builder<trimesh>, "triangles only");
static_assert(hmira::change_counted_mesh<trimesh>, "so indexed adapters can work on it too");
// [capabilities]

// A torus of n x m quads, each split in two triangles: closed, genus 1.
constexpr double big_r = 2.0, small_r = 0.7;
trimesh make_torus(int n, int m) {
    trimesh t;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
            t.add_vertex({float((big_r + small_r * std::cos(v)) * std::cos(u)),
                          float((big_r + small_r * std::cos(v)) * std::sin(u)), float(small_r * std::sin(v))});
        }
    auto id = [&](int i, int j) { return (i % n) * m + (j % m); };
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            t.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            t.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return t;
}

// [generic]
// Generic code that walks all three neighbourhoods of the elements it is given. It neither
// knows nor cares where the answers come from.
template <class M, class T = hmira::default_traits<M>>
    requires hmira::vertex_adjacency_mesh<M, T> && hmira::vertex_face_adjacency_mesh<M, T> &&
             hmira::face_adjacency_mesh<M, T>
std::array<long long, 3> neighbourhood_sums(const M& mesh, const std::vector<int>& vertices,
                                            const std::vector<int>& faces) {
    std::array<long long, 3> sum{};
    for (int v : vertices)
        for (auto w : T::adjacent_vertices(mesh, v)) sum[0] += w;
    for (int v : vertices)
        for (auto f : T::vertex_faces(mesh, v)) sum[1] += f;
    for (int f : faces)
        for (auto g : T::adjacent_faces(mesh, f)) sum[2] += g;
    return sum;
}
// [generic]

template <class F>
double seconds(F&& work) {
    const auto t0 = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Best of three runs, so that the first pass's cold caches do not count against one flavour.
template <class F>
double best_seconds(F&& work) {
    double best = seconds(work);
    for (int i = 0; i < 2; ++i) best = std::min(best, seconds(work));
    return best;
}

template <class Range>
std::vector<int> sorted(const Range& r) {
    std::vector<int> out;
    for (auto x : r) out.push_back(static_cast<int>(x));
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

int main() {
    std::printf("trimesh_like\n");
    {
        trimesh ico;  // the triangle generators write into it
        check(static_cast<bool>(hmira::generate_icosahedron(ico)) && hmira::validate(ico).empty(),
              "generate_icosahedron() fills a trimesh and validate() accepts it");
    }

    const int n = 256, m = 128;
    trimesh mesh = make_torus(n, m);
    const auto topo = hmira::mesh_topology(mesh);
    std::printf("  torus: V=%zu E=%zu F=%zu chi=%lld genus=%lld\n", topo.vertices, topo.edges, topo.faces,
                topo.euler_characteristic, topo.genus);
    check(hmira::validate(mesh).empty() && topo.euler_characteristic == 0 && topo.genus == 1,
          "the triangulated torus is valid, closed, genus 1");

    // vertex_normals needs no adjacency; compare with the torus's analytic normals.
    const auto normals = hmira::vertex_normals(mesh);
    double worst = 1;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < m; ++j) {
            const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / m;
            const auto& q = normals[static_cast<std::size_t>(i * m + j)];
            worst =
                std::min(worst, q.x * std::cos(v) * std::cos(u) + q.y * std::cos(v) * std::sin(u) + q.z * std::sin(v));
        }
    std::printf("  vertex_normals: worst cosine to the analytic normal %.6f\n", worst);
    check(worst > 0.999, "vertex_normals() on float coordinates matches the analytic torus normals");

    // ---- the three ways to answer adjacency --------------------------------------------------
    std::vector<int> all_v(mesh.vertices.size()), all_f(mesh.faces.size()), some_v, some_f;
    for (std::size_t i = 0; i < all_v.size(); ++i) all_v[i] = static_cast<int>(i);
    for (std::size_t i = 0; i < all_f.size(); ++i) all_f[i] = static_cast<int>(i);
    for (std::size_t i = 0; i < all_v.size(); i += all_v.size() / 50) some_v.push_back(static_cast<int>(i));
    for (std::size_t i = 0; i < all_f.size(); i += all_f.size() / 50) some_f.push_back(static_cast<int>(i));
    const double queries_all = 2.0 * double(all_v.size()) + double(all_f.size());
    const double queries_some = 2.0 * double(some_v.size()) + double(some_f.size());

    // [native]
    const double native_build = seconds([&] {
        mesh.need_neighbors();
        mesh.need_adjacentfaces();
        mesh.need_across_edge();
    });
    // [native]
    std::array<long long, 3> native{}, indexed{}, brute{}, native_some{};
    const double native_query = best_seconds([&] { native = neighbourhood_sums(mesh, all_v, all_f); });
    native_some = neighbourhood_sums(mesh, some_v, some_f);

    // [adapters]
    // The adapters take precedence over the mesh's own operations, which forces each flavour.
    std::optional<hmira::with_indexed_adjacency<trimesh>> by_index;
    const double indexed_build = seconds([&] { by_index.emplace(mesh); });
    const double indexed_query = best_seconds([&] { indexed = neighbourhood_sums(*by_index, all_v, all_f); });
    const auto by_scan = hmira::adapt_brute_force(mesh);
    const double brute_query = seconds([&] { brute = neighbourhood_sums(by_scan, some_v, some_f); });
    // [adapters]

    std::size_t native_bytes = 0;
    for (const auto& row : mesh.neighbors) native_bytes += row.capacity() * sizeof(int) + sizeof(row);
    for (const auto& row : mesh.adjacentfaces) native_bytes += row.capacity() * sizeof(int) + sizeof(row);
    native_bytes += mesh.across_edge.capacity() * sizeof(trimesh::face);
    using va = hmira::indexed_vertex_adjacency<trimesh>;
    using vf = hmira::indexed_vertex_face_adjacency<trimesh>;
    using ff = hmira::indexed_face_adjacency<trimesh>;
    const std::size_t index_bytes = by_index->adapter<va>().memory_bytes() + by_index->adapter<vf>().memory_bytes() +
                                    by_index->adapter<ff>().memory_bytes();

    const double per_native = native_query / queries_all * 1e9, per_indexed = indexed_query / queries_all * 1e9;
    const double per_brute = brute_query / queries_some * 1e9;
    std::printf(
        "\n  cost of one neighbourhood query (V_adjacentV, F_adjacentV, F_adjacentF), %zu vertices, %zu faces:\n",
        all_v.size(), all_f.size());
    std::printf("  %-26s %14s %14s %18s\n", "", "native arrays", "indexed adapt", "brute-force adapt");
    std::printf("  %-26s %14.1f %14.1f %18.0f\n", "ns per query", per_native, per_indexed, per_brute);
    std::printf("  %-26s %14.2f %14.2f %18s\n", "build once (ms)", native_build * 1e3, indexed_build * 1e3, "0");
    std::printf("  %-26s %14.2f %14.2f %18.0f\n", "every element once (ms)", (native_build + native_query) * 1e3,
                (indexed_build + indexed_query) * 1e3, per_brute * queries_all * 1e-6);
    std::printf("  %-26s %14.2f %14.2f %18s\n", "extra memory (MiB)", double(native_bytes) / (1 << 20),
                double(index_bytes) / (1 << 20), "0");
    std::printf("  brute force per query is %.0fx the native arrays\n\n", per_brute / per_native);

    check(native == indexed, "native arrays and indexed adapters give the same neighbourhoods (all elements)");
    check(native_some == brute, "native arrays and brute-force adapters give the same neighbourhoods (sample)");
    bool same_sets = true;
    for (int v : some_v) {
        same_sets &= sorted(hmira::mesh_traits<trimesh>::adjacent_vertices(mesh, v)) ==
                     sorted(hmira::default_traits<decltype(by_scan)>::adjacent_vertices(by_scan, v));
    }
    check(same_sets, "... and the same vertex sets, not only the same sums");
    check(per_brute > 10 * per_native, "brute force costs O(F_all) per query, native O(V_adjacentV)");

    // An edit leaves the native arrays empty and the indexed adapters stale: both refuse.
    mesh.add_vertex({0, 0, 9});
    bool native_refused = false, index_refused = false;
    try {
        (void)hmira::mesh_traits<trimesh>::adjacent_vertices(mesh, 0);
    } catch (const hmira::hmira_error&) {
        native_refused = true;
    }
    try {
        (void)hmira::default_traits<decltype(*by_index)>::adjacent_vertices(*by_index, 0);
    } catch (const hmira::hmira_error&) {
        index_refused = true;
    }
    check(native_refused && index_refused, "after an edit, stale connectivity throws instead of answering");

    std::printf("%s\n", failures == 0 ? "all checks passed" : "SOME CHECKS FAILED");
    return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
