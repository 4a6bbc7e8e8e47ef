// Core benchmarks: each model built from an indexed face list, a one-ring traversal
// summing neighbour positions, flip normals, and the adapter flavours, on a real mesh and a
// synthetic 2M-triangle grid; OpenMesh and CGAL run natively and through hmira traits.
//
//   bench_core [google-benchmark flags]      Google Benchmark over every workload
//   bench_core --pairs [rounds [workload [mesh]]]  interleaved native/hmira pairs, median
//                                            ratios; optionally only one workload (build,
//                                            one_ring, flip) and meshes whose name contains `mesh`
//
// The real mesh is $HMIRA_TEST_DATA/meshes/armadillo.off (elephant.off as fallback); the pairs
// also run on elephant.off refined twice (89k triangles), a size where per-call costs show.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_map>
#include <vector>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#include <hmira/meshes/winged_edge_mesh.hpp>

#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/boost/graph/iterator.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

// ---------------------------------------------------------------------------------------------
// Input: an indexed face list.

struct face_list {
    std::string name;
    std::vector<hmira::vec3<double>> points;
    std::vector<std::uint32_t> offsets{0}, corners;
    std::size_t faces() const { return offsets.size() - 1; }
};

face_list triangle_grid(std::size_t nx, std::size_t ny, std::string name) {
    face_list g;
    g.name = std::move(name);
    for (std::size_t j = 0; j <= ny; ++j)
        for (std::size_t i = 0; i <= nx; ++i)
            g.points.push_back({double(i), double(j), 0.001 * double((i * 7 + j * 13) % 17)});
    auto id = [&](std::size_t i, std::size_t j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    for (std::size_t j = 0; j < ny; ++j)
        for (std::size_t i = 0; i < nx; ++i) {
            const auto a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
            for (auto v : {a, b, c}) g.corners.push_back(v);
            g.offsets.push_back(static_cast<std::uint32_t>(g.corners.size()));
            for (auto v : {a, c, d}) g.corners.push_back(v);
            g.offsets.push_back(static_cast<std::uint32_t>(g.corners.size()));
        }
    return g;
}

// A minimal OFF reader, so the benchmark does not depend on the io module's evolving API.
bool read_off(const std::string& path, face_list& out) {
    std::ifstream in(path);
    if (!in) return false;
    std::string header;
    in >> header;
    if (header != "OFF") return false;
    std::size_t nv = 0, nf = 0, ne = 0;
    in >> nv >> nf >> ne;
    out.points.resize(nv);
    for (auto& p : out.points) in >> p.x >> p.y >> p.z;
    for (std::size_t f = 0; f < nf; ++f) {
        std::size_t k = 0;
        in >> k;
        for (std::size_t i = 0; i < k; ++i) {
            std::uint32_t v = 0;
            in >> v;
            out.corners.push_back(v);
        }
        out.offsets.push_back(static_cast<std::uint32_t>(out.corners.size()));
        std::string rest;
        std::getline(in, rest);
    }
    return static_cast<bool>(in);
}

std::string test_data_dir() {
    const char* dir = std::getenv("HMIRA_TEST_DATA");
    return dir ? dir : "build/test-data";
}

const face_list& real_mesh() {
    static const face_list mesh = [] {
        face_list g;
        const std::string dir = test_data_dir();
        for (const char* name : {"armadillo", "elephant"}) {
            face_list t;
            t.name = name;
            if (read_off(dir + "/meshes/" + name + ".off", t)) return t;
        }
        std::fprintf(stderr,
                     "bench_core: no real mesh under %s/meshes (run scripts/test-data.sh); using a 160x160 grid\n",
                     dir.c_str());
        return triangle_grid(160, 160, "grid-51k(fallback)");
    }();
    return mesh;
}
// Each triangle split into four at its edge midpoints, `levels` times: the issue's "refined
// elephant" (5.6k -> 89k triangles at two levels), a mid-sized mesh in the real mesh's order.
face_list refined(face_list g, int levels, std::string name) {
    g.name = std::move(name);
    for (int level = 0; level < levels; ++level) {
        std::unordered_map<std::uint64_t, std::uint32_t> midpoint;
        auto mid = [&](std::uint32_t a, std::uint32_t b) {
            const auto key = (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
            auto [it, fresh] = midpoint.try_emplace(key, static_cast<std::uint32_t>(g.points.size()));
            if (fresh) g.points.push_back((g.points[a] + g.points[b]) * 0.5);
            return it->second;
        };
        face_list out;
        for (std::size_t f = 0; f < g.faces(); ++f) {
            if (g.offsets[f + 1] - g.offsets[f] != 3) return {};  // triangles only
            const auto a = g.corners[g.offsets[f]], b = g.corners[g.offsets[f] + 1], c = g.corners[g.offsets[f] + 2];
            const auto ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            for (auto t :
                 {std::array{a, ab, ca}, std::array{ab, b, bc}, std::array{ca, bc, c}, std::array{ab, bc, ca}}) {
                out.corners.insert(out.corners.end(), t.begin(), t.end());
                out.offsets.push_back(static_cast<std::uint32_t>(out.corners.size()));
            }
        }
        g.corners = std::move(out.corners);
        g.offsets = std::move(out.offsets);
    }
    return g;
}
const face_list& refined_elephant() {
    static const face_list mesh = [] {
        face_list g;
        const std::string dir = test_data_dir();
        if (!read_off(dir + "/meshes/elephant.off", g)) return face_list{};
        return refined(std::move(g), 2, "elephant-refined");
    }();
    return mesh;
}
const face_list& grid_2m() {
    static const face_list g = triangle_grid(1000, 1000, "grid-2M");
    return g;
}
const face_list& grid_10k() {
    static const face_list g = triangle_grid(70, 72, "grid-10k");
    return g;
}

// ---------------------------------------------------------------------------------------------
// The generic (hmira) side: written once against traits.

template <class M, class T = hmira::default_traits<M>>
void build_through_traits(M& m, const face_list& g) {
    using S = typename T::scalar;
    // Models that can reserve room (OpenMesh, CGAL, winged-edge) do, as their native builds do.
    if constexpr (requires { T::reserve(m, std::size_t{}, std::size_t{}, std::size_t{}); })
        T::reserve(m, g.points.size(), g.corners.size() / 2 + g.points.size(), g.faces());
    std::vector<typename T::vertex_handle> vs;
    vs.reserve(g.points.size());
    for (const auto& p : g.points) vs.push_back(T::add_vertex(m, hmira::vec3<S>{S(p.x), S(p.y), S(p.z)}));
    std::vector<typename T::vertex_handle> face;
    for (std::size_t f = 0; f < g.faces(); ++f) {
        face.clear();
        for (auto k = g.offsets[f]; k < g.offsets[f + 1]; ++k) face.push_back(vs[g.corners[k]]);
        if (!T::add_face(m, std::span<const typename T::vertex_handle>(face))) std::abort();
    }
}

// The traversals are kept out of line, the peers' native loops too, so that each side is compiled
// alone: inlined into the benchmark lambda (which reads only .x) the template one lost its y and
// z sums but spilled its cursor to the stack, while the native functions stayed out of line.
template <class M, class T = hmira::default_traits<M>>
    requires hmira::vertex_adjacency_mesh<M, T> && hmira::positioned_mesh<M, T>
[[gnu::noinline]] hmira::vec3<double> one_ring_sum(const M& m) {
    hmira::vec3<double> s{};
    for (auto v : T::vertices(m))
        for (auto w : T::adjacent_vertices(m, v)) {
            const auto& p = T::position(m, w);  // as the native loops read it: no copy of the point
            s.x += p.x;
            s.y += p.y;
            s.z += p.z;
        }
    return s;
}

hmira::halfedge_mesh bulk_halfedge(const face_list& g) {
    auto r = hmira::halfedge_mesh::from_polygons(g.points, g.offsets, g.corners);
    if (!r) std::abort();
    return std::move(*r);
}
// The same mesh with float positions, as OpenMesh's default points: on a mesh too large for the
// caches the one-ring is bound by memory traffic, and double positions are twice the bytes.
hmira::basic_halfedge_mesh<float> bulk_halfedge_float(const face_list& g) {
    std::vector<hmira::vec3<float>> points;
    points.reserve(g.points.size());
    for (const auto& p : g.points) points.push_back({float(p.x), float(p.y), float(p.z)});
    auto r = hmira::basic_halfedge_mesh<float>::from_polygons(points, g.offsets, g.corners);
    if (!r) std::abort();
    return std::move(*r);
}
// halfedge_mesh's traits as they were before they offered reserve and reverse_orientation:
// the "before" side of the build and flip rows, measured in the same run.
struct halfedge_traits_before : hmira::mesh_traits<hmira::halfedge_mesh> {
    static void reserve(hmira::halfedge_mesh&, std::size_t, std::size_t, std::size_t) = delete;
    static void reverse_orientation(hmira::halfedge_mesh&) = delete;
};

template <class M>
M built(const face_list& g) {
    M m;
    build_through_traits(m, g);
    return m;
}

// ---------------------------------------------------------------------------------------------
// The peers, driven natively by their own API.

#ifdef HMIRA_BENCH_WITH_OPENMESH
using om_mesh = OpenMesh::PolyMesh_ArrayKernelT<>;

void om_build_native(om_mesh& m, const face_list& g) {
    m.reserve(g.points.size(), g.corners.size() / 2 + g.points.size(), g.faces());
    std::vector<OpenMesh::VertexHandle> vs;
    vs.reserve(g.points.size());
    for (const auto& p : g.points) vs.push_back(m.add_vertex(om_mesh::Point(float(p.x), float(p.y), float(p.z))));
    std::vector<OpenMesh::VertexHandle> face;
    for (std::size_t f = 0; f < g.faces(); ++f) {
        face.clear();
        for (auto k = g.offsets[f]; k < g.offsets[f + 1]; ++k) face.push_back(vs[g.corners[k]]);
        if (!m.add_face(face).is_valid()) std::abort();
    }
}
[[gnu::noinline]] hmira::vec3<double> om_one_ring_native(const om_mesh& m) {
    hmira::vec3<double> s{};
    for (auto v : m.vertices())
        for (auto w : m.vv_range(v)) {
            const auto& p = m.point(w);
            s.x += p[0];
            s.y += p[1];
            s.z += p[2];
        }
    return s;
}
// hmira::flip_normals's steps, written against OpenMesh's API: the same loop natively.
void om_flip_native(om_mesh& m) {
    using HH = OpenMesh::HalfedgeHandle;
    using VH = OpenMesh::VertexHandle;
    const std::size_t nh = m.n_halfedges();
    std::vector<HH> old_prev(nh);
    std::vector<VH> source(nh);
    std::vector<HH> all;
    all.reserve(nh);
    for (auto h : m.halfedges()) {
        old_prev[h.idx()] = m.prev_halfedge_handle(h);
        source[h.idx()] = m.from_vertex_handle(h);
        all.push_back(h);
    }
    std::vector<std::pair<VH, HH>> out;
    out.reserve(m.n_vertices());
    for (auto v : m.vertices()) {
        const HH h = m.halfedge_handle(v);
        if (!h.is_valid()) continue;
        out.emplace_back(v, m.is_boundary(h) ? old_prev[h.idx()] : m.opposite_halfedge_handle(h));
    }
    for (HH h : all) {
        m.set_vertex_handle(h, source[h.idx()]);
        m.set_next_halfedge_handle(h, old_prev[h.idx()]);
    }
    for (const auto& [v, h] : out) m.set_halfedge_handle(v, h);
}
om_mesh om_built(const face_list& g) {
    om_mesh m;
    om_build_native(m, g);
    return m;
}
#endif

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using cgal_point = cgal_kernel::Point_3;
using cgal_mesh = CGAL::Surface_mesh<cgal_point>;

struct cgal_soup {
    std::vector<cgal_point> points;
    std::vector<std::vector<std::size_t>> polygons;
};
const cgal_soup& soup_of(const face_list& g) {
    static std::vector<std::pair<const face_list*, std::unique_ptr<cgal_soup>>> cache;
    for (auto& [k, v] : cache)
        if (k == &g) return *v;
    auto s = std::make_unique<cgal_soup>();
    for (const auto& p : g.points) s->points.emplace_back(p.x, p.y, p.z);
    for (std::size_t f = 0; f < g.faces(); ++f)
        s->polygons.emplace_back(g.corners.begin() + g.offsets[f], g.corners.begin() + g.offsets[f + 1]);
    cache.emplace_back(&g, std::move(s));
    return *cache.back().second;
}
void cgal_build_soup(cgal_mesh& m, const face_list& g, bool checked) {
    const auto& s = soup_of(g);
    if (checked && !CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(s.polygons)) std::abort();
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(s.points, s.polygons, m);
}
void cgal_build_native(cgal_mesh& m, const face_list& g) {
    m.reserve(static_cast<cgal_mesh::size_type>(g.points.size()),
              static_cast<cgal_mesh::size_type>(g.corners.size() / 2 + g.points.size()),
              static_cast<cgal_mesh::size_type>(g.faces()));
    std::vector<cgal_mesh::Vertex_index> vs;
    vs.reserve(g.points.size());
    for (const auto& p : g.points) vs.push_back(m.add_vertex(cgal_point(p.x, p.y, p.z)));
    std::vector<cgal_mesh::Vertex_index> face;
    for (std::size_t f = 0; f < g.faces(); ++f) {
        face.clear();
        for (auto k = g.offsets[f]; k < g.offsets[f + 1]; ++k) face.push_back(vs[g.corners[k]]);
        if (m.add_face(face) == cgal_mesh::null_face()) std::abort();
    }
}
[[gnu::noinline]] hmira::vec3<double> cgal_one_ring_native(const cgal_mesh& m) {
    hmira::vec3<double> s{};
    for (auto v : m.vertices()) {
        if (m.halfedge(v) == cgal_mesh::null_halfedge()) continue;
        for (auto w : CGAL::vertices_around_target(m.halfedge(v), m)) {
            const auto& p = m.point(w);
            s.x += p.x();
            s.y += p.y();
            s.z += p.z();
        }
    }
    return s;
}
// hmira::flip_normals's steps, written against Surface_mesh's API: the same loop natively.
void cgal_flip_native(cgal_mesh& m) {
    using HH = cgal_mesh::Halfedge_index;
    using VH = cgal_mesh::Vertex_index;
    const std::size_t nh = m.num_halfedges();
    std::vector<HH> old_prev(nh);
    std::vector<VH> source(nh);
    std::vector<HH> all;
    all.reserve(nh);
    for (auto h : m.halfedges()) {
        old_prev[h.idx()] = m.prev(h);
        source[h.idx()] = m.source(h);
        all.push_back(h);
    }
    // Surface_mesh keeps an incoming halfedge per vertex; after the flip the old outgoing
    // (its opposite's direction reversed) comes in.
    std::vector<std::pair<VH, HH>> in;
    in.reserve(m.number_of_vertices());
    for (auto v : m.vertices()) {
        const HH h = m.halfedge(v);
        if (h == cgal_mesh::null_halfedge()) continue;
        in.emplace_back(v, m.is_border(h) ? m.next(h) : m.opposite(h));
    }
    for (HH h : all) {
        m.set_target(h, source[h.idx()]);
        m.set_next(h, old_prev[h.idx()]);
    }
    for (const auto& [v, h] : in) m.set_halfedge(v, h);
}
cgal_mesh cgal_built(const face_list& g) {
    cgal_mesh m;
    cgal_build_soup(m, g, false);
    return m;
}
#endif

// ---------------------------------------------------------------------------------------------
// Google Benchmark registrations.

template <class F>
void register_bench(const std::string& name, F f) {
    benchmark::RegisterBenchmark(name.c_str(), [f](benchmark::State& state) {
        f(state);
    })->Unit(benchmark::kMillisecond);
}

void register_all() {
    for (const face_list* g : {&real_mesh(), &grid_2m()}) {
        const std::string n = "/" + g->name;
        // Building.
        register_bench("build/halfedge_mesh/bulk_from_polygons" + n, [g](benchmark::State& s) {
            for (auto _ : s) {
                auto m = bulk_halfedge(*g);
                benchmark::DoNotOptimize(m.edge_count());
            }
        });
        register_bench("build/halfedge_mesh/add_face" + n, [g](benchmark::State& s) {
            for (auto _ : s) {
                auto m = built<hmira::halfedge_mesh>(*g);
                benchmark::DoNotOptimize(m.edge_count());
            }
        });
        register_bench("build/winged_edge_mesh/add_face" + n, [g](benchmark::State& s) {
            for (auto _ : s) {
                auto m = built<hmira::winged_edge_mesh>(*g);
                benchmark::DoNotOptimize(m.edge_count());
            }
        });
        register_bench("build/face_vertex_mesh/add_face" + n, [g](benchmark::State& s) {
            for (auto _ : s) {
                auto m = built<hmira::face_vertex_mesh>(*g);
                benchmark::DoNotOptimize(m.face_count());
            }
        });
#ifdef HMIRA_BENCH_WITH_OPENMESH
        register_bench("build/openmesh/native_add_face" + n, [g](benchmark::State& s) {
            for (auto _ : s) {
                om_mesh m;
                om_build_native(m, *g);
                benchmark::DoNotOptimize(m.n_faces());
            }
        });
        register_bench("build/openmesh/hmira_traits_add_face" + n, [g](benchmark::State& s) {
            for (auto _ : s) {
                om_mesh m;
                build_through_traits(m, *g);
                benchmark::DoNotOptimize(m.n_faces());
            }
        });
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
        register_bench("build/cgal/native_polygon_soup_to_polygon_mesh" + n, [g](benchmark::State& s) {
            (void)soup_of(*g);
            for (auto _ : s) {
                cgal_mesh m;
                cgal_build_soup(m, *g, false);
                benchmark::DoNotOptimize(m.number_of_faces());
            }
        });
        register_bench("build/cgal/native_soup_checked" + n, [g](benchmark::State& s) {
            (void)soup_of(*g);
            for (auto _ : s) {
                cgal_mesh m;
                cgal_build_soup(m, *g, true);
                benchmark::DoNotOptimize(m.number_of_faces());
            }
        });
        register_bench("build/cgal/native_add_face" + n, [g](benchmark::State& s) {
            for (auto _ : s) {
                cgal_mesh m;
                cgal_build_native(m, *g);
                benchmark::DoNotOptimize(m.number_of_faces());
            }
        });
        register_bench("build/cgal/hmira_traits_add_face" + n, [g](benchmark::State& s) {
            for (auto _ : s) {
                cgal_mesh m;
                build_through_traits(m, *g);
                benchmark::DoNotOptimize(m.number_of_faces());
            }
        });
#endif
        // One-ring traversal.
        register_bench("one_ring/halfedge_mesh" + n, [g](benchmark::State& s) {
            const auto m = bulk_halfedge(*g);
            for (auto _ : s) benchmark::DoNotOptimize(one_ring_sum(m));
        });
        register_bench("one_ring/winged_edge_mesh" + n, [g](benchmark::State& s) {
            const auto m = built<hmira::winged_edge_mesh>(*g);
            for (auto _ : s) benchmark::DoNotOptimize(one_ring_sum(m));
        });
        register_bench("one_ring/face_vertex_mesh+indexed_adapter(query)" + n, [g](benchmark::State& s) {
            auto m = built<hmira::face_vertex_mesh>(*g);
            const auto a = hmira::adapt_indexed(m);
            for (auto _ : s) benchmark::DoNotOptimize(one_ring_sum(a));
        });
        register_bench("adapter/indexed_vertex_adjacency(build)" + n, [g](benchmark::State& s) {
            auto m = built<hmira::face_vertex_mesh>(*g);
            for (auto _ : s) {
                hmira::indexed_vertex_adjacency<hmira::face_vertex_mesh> a(m);
                benchmark::DoNotOptimize(a.memory_bytes());
            }
        });
        register_bench("adapter/indexed_all(build)" + n, [g](benchmark::State& s) {
            auto m = built<hmira::face_vertex_mesh>(*g);
            for (auto _ : s) {
                auto a = hmira::adapt_indexed(m);
                benchmark::DoNotOptimize(&a);
            }
        });
#ifdef HMIRA_BENCH_WITH_OPENMESH
        register_bench("one_ring/openmesh/native_vv_range" + n, [g](benchmark::State& s) {
            const auto m = om_built(*g);
            for (auto _ : s) benchmark::DoNotOptimize(om_one_ring_native(m));
        });
        register_bench("one_ring/openmesh/hmira_traits" + n, [g](benchmark::State& s) {
            const auto m = om_built(*g);
            for (auto _ : s) benchmark::DoNotOptimize(one_ring_sum(m));
        });
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
        register_bench("one_ring/cgal/native_vertices_around_target" + n, [g](benchmark::State& s) {
            const auto m = cgal_built(*g);
            for (auto _ : s) benchmark::DoNotOptimize(cgal_one_ring_native(m));
        });
        register_bench("one_ring/cgal/hmira_traits" + n, [g](benchmark::State& s) {
            const auto m = cgal_built(*g);
            for (auto _ : s) benchmark::DoNotOptimize(one_ring_sum(m));
        });
#endif
        // Flip normals.
        register_bench("flip/halfedge_mesh" + n, [g](benchmark::State& s) {
            auto m = bulk_halfedge(*g);
            for (auto _ : s) benchmark::DoNotOptimize(hmira::flip_normals(m));
        });
        register_bench("flip/winged_edge_mesh" + n, [g](benchmark::State& s) {
            auto m = built<hmira::winged_edge_mesh>(*g);
            for (auto _ : s) benchmark::DoNotOptimize(hmira::flip_normals(m));
        });
        register_bench("flip/face_vertex_mesh" + n, [g](benchmark::State& s) {
            auto m = built<hmira::face_vertex_mesh>(*g);
            for (auto _ : s) benchmark::DoNotOptimize(hmira::flip_normals(m));
        });
#ifdef HMIRA_BENCH_WITH_OPENMESH
        register_bench("flip/openmesh/native_loop" + n, [g](benchmark::State& s) {
            auto m = om_built(*g);
            for (auto _ : s) om_flip_native(m);
        });
        register_bench("flip/openmesh/hmira_flip_normals" + n, [g](benchmark::State& s) {
            auto m = om_built(*g);
            for (auto _ : s) benchmark::DoNotOptimize(hmira::flip_normals(m));
        });
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
        register_bench("flip/cgal/native_loop" + n, [g](benchmark::State& s) {
            auto m = cgal_built(*g);
            for (auto _ : s) cgal_flip_native(m);
        });
        register_bench("flip/cgal/PMP_reverse_face_orientations" + n, [g](benchmark::State& s) {
            auto m = cgal_built(*g);
            for (auto _ : s) CGAL::Polygon_mesh_processing::reverse_face_orientations(m);
        });
        register_bench("flip/cgal/hmira_flip_normals" + n, [g](benchmark::State& s) {
            auto m = cgal_built(*g);
            for (auto _ : s) benchmark::DoNotOptimize(hmira::flip_normals(m));
        });
#endif
    }
    // Brute force on the 10k-face mesh only: O(F_all) per query.
    const face_list* small = &grid_10k();
    register_bench("one_ring/face_vertex_mesh+brute_force_adapter/" + small->name, [small](benchmark::State& s) {
        auto m = built<hmira::face_vertex_mesh>(*small);
        const auto a = hmira::adapt_brute_force(m);
        for (auto _ : s) benchmark::DoNotOptimize(one_ring_sum(a));
    });
    register_bench("one_ring/face_vertex_mesh+indexed_adapter(build+query)/" + small->name,
                   [small](benchmark::State& s) {
                       auto m = built<hmira::face_vertex_mesh>(*small);
                       for (auto _ : s) {
                           const auto a = hmira::adapt_indexed(m);
                           benchmark::DoNotOptimize(one_ring_sum(a));
                       }
                   });
    register_bench("one_ring/halfedge_mesh/" + small->name, [small](benchmark::State& s) {
        const auto m = bulk_halfedge(*small);
        for (auto _ : s) benchmark::DoNotOptimize(one_ring_sum(m));
    });
}

// ---------------------------------------------------------------------------------------------
// Interleaved pairs: peer and hmira alternate (order swapped every round) so that machine
// noise hits both; the ratio of each round is taken and the median reported. Times are the
// process's CPU time (user + system, so the kernel's zeroing of fresh pages counts), not wall
// time: the machine is shared, and a benchmark waiting for a core is not doing work.

double cpu_now() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct pair_spec {
    std::string workload, mesh, peer, hmira;
    std::function<double()> run_peer, run_hmira;  // each returns seconds for one run
    double target = 0;
    int repeat = 1;  // set for traversal and flip pairs on the small mesh
};

// Short workloads (a traversal of the small mesh) run `repeat` times per sample.
int repeat = 1;
template <class F>
double seconds(F&& f) {
    const double t0 = cpu_now();
    for (int i = 0; i < repeat; ++i) f();
    return (cpu_now() - t0) / repeat;
}

/// Seconds per build: `make()` builds a fresh mesh `repeat` times; every mesh is kept until the
/// timing ends, so freeing it (munmap of its arrays) counts for no side, and no repetition
/// builds into an earlier one's mesh.
template <class Make>
double build_seconds(Make&& make) {
    std::vector<decltype(make())> kept;
    kept.reserve(std::size_t(repeat));
    return seconds([&] { kept.push_back(make()); });
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const auto n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

volatile double sink = 0;

void run_pairs(int rounds, const std::string& workload_filter, const std::string& mesh_filter) {
    std::vector<pair_spec> pairs;
    for (const face_list* g : {&real_mesh(), &refined_elephant(), &grid_2m()}) {
        if (g->faces() == 0) continue;  // no elephant.off: the real mesh and the grid only
        const int reps = g->faces() < 200000 ? 20 : 1;
        const std::size_t first = pairs.size();
        const std::string mesh = g->name + " (" + std::to_string(g->faces()) + " F)";
        // Shared prebuilt meshes for the traversal and flip workloads.
        auto he = std::make_shared<hmira::halfedge_mesh>(bulk_halfedge(*g));
        auto bulk = [g] {
            return build_seconds([&] { return std::make_unique<hmira::halfedge_mesh>(bulk_halfedge(*g)); });
        };
        auto one_by_one = [g] {
            return build_seconds(
                [&] { return std::make_unique<hmira::halfedge_mesh>(built<hmira::halfedge_mesh>(*g)); });
        };
        auto he_ring = [he] { return seconds([&] { sink = one_ring_sum(*he).x; }); };
        auto one_by_one_before = [g] {
            return build_seconds([&] {
                auto m = std::make_unique<hmira::halfedge_mesh>();
                build_through_traits<hmira::halfedge_mesh, halfedge_traits_before>(*m, *g);
                return m;
            });
        };
        auto he_flip = [he] { return seconds([&] { sink = double(hmira::flip_normals(*he)); }); };
        auto he_flip_before = [he] {
            return seconds(
                [&] { sink = double(hmira::flip_normals<hmira::halfedge_mesh, halfedge_traits_before>(*he)); });
        };
        (void)one_by_one_before;  // the peers' sections use these when their libraries are found
        (void)he_flip;
        (void)he_flip_before;
#ifdef HMIRA_BENCH_WITH_OPENMESH
        auto om = std::make_shared<om_mesh>(om_built(*g));
        auto om_native_build = [g] {
            return build_seconds([&] {
                auto m = std::make_unique<om_mesh>();
                om_build_native(*m, *g);
                return m;
            });
        };
        auto om_traits_build = [g] {
            return build_seconds([&] {
                auto m = std::make_unique<om_mesh>();
                build_through_traits(*m, *g);
                return m;
            });
        };
        auto om_native_ring = [om] { return seconds([&] { sink = om_one_ring_native(*om).x; }); };
        pairs.push_back(
            {"build", mesh, "OpenMesh add_face", "halfedge_mesh::from_polygons", om_native_build, bulk, 0.5});
        pairs.push_back({"build", mesh, "OpenMesh add_face", "halfedge_mesh add_face (one at a time)", om_native_build,
                         one_by_one, 0.5});
        pairs.push_back({"build", mesh, "OpenMesh add_face", "halfedge_mesh add_face, before (no reserve)",
                         om_native_build, one_by_one_before, 0});
        pairs.push_back(
            {"build", mesh, "OpenMesh add_face", "OpenMesh via hmira traits", om_native_build, om_traits_build, 1.05});
        pairs.push_back({"one_ring", mesh, "OpenMesh vv_range", "OpenMesh via hmira traits", om_native_ring,
                         [om] { return seconds([&] { sink = one_ring_sum(*om).x; }); }, 1.05});
        pairs.push_back({"one_ring", mesh, "OpenMesh vv_range", "halfedge_mesh", om_native_ring, he_ring, 1.0});
        auto he_float = std::make_shared<hmira::basic_halfedge_mesh<float>>(bulk_halfedge_float(*g));
        pairs.push_back({"one_ring", mesh, "OpenMesh vv_range", "halfedge_mesh<float> (OM-sized points)",
                         om_native_ring, [he_float] { return seconds([&] { sink = one_ring_sum(*he_float).x; }); }, 0});
        pairs.push_back({"flip", mesh, "OpenMesh native loop", "hmira::flip_normals on OpenMesh",
                         [om] { return seconds([&] { om_flip_native(*om); }); },
                         [om] { return seconds([&] { sink = double(hmira::flip_normals(*om)); }); }, 1.05});
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
        (void)soup_of(*g);
        auto cg = std::make_shared<cgal_mesh>(cgal_built(*g));
        auto cgal_soup_build = [g] {
            return build_seconds([&] {
                auto m = std::make_unique<cgal_mesh>();
                cgal_build_soup(*m, *g, false);
                return m;
            });
        };
        auto cgal_soup_checked = [g] {
            return build_seconds([&] {
                auto m = std::make_unique<cgal_mesh>();
                cgal_build_soup(*m, *g, true);
                return m;
            });
        };
        auto cgal_native_add = [g] {
            return build_seconds([&] {
                auto m = std::make_unique<cgal_mesh>();
                cgal_build_native(*m, *g);
                return m;
            });
        };
        auto cgal_traits_add = [g] {
            return build_seconds([&] {
                auto m = std::make_unique<cgal_mesh>();
                build_through_traits(*m, *g);
                return m;
            });
        };
        auto cgal_native_ring = [cg] { return seconds([&] { sink = cgal_one_ring_native(*cg).x; }); };
        pairs.push_back({"build", mesh, "CGAL polygon_soup_to_polygon_mesh", "halfedge_mesh::from_polygons",
                         cgal_soup_build, bulk, 0.5});
        pairs.push_back({"build", mesh, "CGAL soup, checked is_polygon_soup_a_polygon_mesh",
                         "halfedge_mesh::from_polygons", cgal_soup_checked, bulk, 0});
        pairs.push_back({"build", mesh, "CGAL polygon_soup_to_polygon_mesh", "halfedge_mesh add_face (one at a time)",
                         cgal_soup_build, one_by_one, 0.5});
        pairs.push_back({"build", mesh, "CGAL add_face", "halfedge_mesh add_face (one at a time)", cgal_native_add,
                         one_by_one, 0.5});
        pairs.push_back({"build", mesh, "CGAL add_face", "halfedge_mesh add_face, before (no reserve)", cgal_native_add,
                         one_by_one_before, 0});
        pairs.push_back(
            {"build", mesh, "CGAL add_face", "CGAL via hmira traits", cgal_native_add, cgal_traits_add, 1.05});
        pairs.push_back({"one_ring", mesh, "CGAL vertices_around_target", "CGAL via hmira traits", cgal_native_ring,
                         [cg] { return seconds([&] { sink = one_ring_sum(*cg).x; }); }, 1.05});
        pairs.push_back(
            {"one_ring", mesh, "CGAL vertices_around_target", "halfedge_mesh", cgal_native_ring, he_ring, 1.0});
        pairs.push_back({"flip", mesh, "CGAL native loop", "hmira::flip_normals on CGAL",
                         [cg] { return seconds([&] { cgal_flip_native(*cg); }); },
                         [cg] { return seconds([&] { sink = double(hmira::flip_normals(*cg)); }); }, 1.05});
        pairs.push_back(
            {"flip", mesh, "CGAL PMP::reverse_face_orientations", "hmira::flip_normals on CGAL",
             [cg] { return seconds([&] { CGAL::Polygon_mesh_processing::reverse_face_orientations(*cg); }); },
             [cg] { return seconds([&] { sink = double(hmira::flip_normals(*cg)); }); }, 1.0});
        pairs.push_back(
            {"flip", mesh, "CGAL PMP::reverse_face_orientations", "halfedge_mesh flip_normals (one pass)",
             [cg] { return seconds([&] { CGAL::Polygon_mesh_processing::reverse_face_orientations(*cg); }); }, he_flip,
             1.0});
        pairs.push_back(
            {"flip", mesh, "CGAL PMP::reverse_face_orientations", "halfedge_mesh flip_normals, before (generic)",
             [cg] { return seconds([&] { CGAL::Polygon_mesh_processing::reverse_face_orientations(*cg); }); },
             he_flip_before, 0});
#endif
        for (std::size_t i = first; i < pairs.size(); ++i) pairs[i].repeat = reps;
    }
    std::printf("%-9s %-22s %-50s %-40s %12s %12s %8s %7s\n", "workload", "mesh", "peer", "hmira", "peer CPU ms",
                "hmira CPU ms", "ratio", "target");
    for (auto& p : pairs) {
        if (!workload_filter.empty() && p.workload != workload_filter) continue;
        if (!mesh_filter.empty() && p.mesh.find(mesh_filter) == std::string::npos) continue;
        std::vector<double> tp, th, ratio;
        // A build of the real mesh takes a few ms, so one build per round left the per-round
        // ratio at the mercy of a single scheduler hiccup on a shared machine (1.02 one night,
        // 1.07 the next for the same code): each round times 5 builds of it (a quarter of the
        // traversal repeats), grid-2M still one.
        repeat = p.workload == "build" ? std::max(1, p.repeat / 4) : p.repeat;
        (void)p.run_peer();  // warm-up
        (void)p.run_hmira();
        for (int r = 0; r < rounds; ++r) {
            double a, b;
            if (r % 2 == 0) {
                a = p.run_peer();
                b = p.run_hmira();
            } else {
                b = p.run_hmira();
                a = p.run_peer();
            }
            tp.push_back(a);
            th.push_back(b);
            ratio.push_back(b / a);
        }
        const double mr = median(ratio);
        char target[16] = "-";
        if (p.target > 0) std::snprintf(target, sizeof target, "%s%.2f", mr <= p.target ? "ok<=" : "NO>", p.target);
        std::printf("%-9s %-22s %-50s %-40s %12.2f %12.2f %8.3f %7s\n", p.workload.c_str(), p.mesh.c_str(),
                    p.peer.c_str(), p.hmira.c_str(), 1e3 * median(tp), 1e3 * median(th), mr, target);
        std::fflush(stdout);
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc >= 2 && std::strcmp(argv[1], "--pairs") == 0) {
        const int rounds = argc >= 3 ? std::max(10, std::atoi(argv[2])) : 11;
        run_pairs(rounds, argc >= 4 ? argv[3] : "", argc >= 5 ? argv[4] : "");
        return 0;
    }
    register_all();
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
