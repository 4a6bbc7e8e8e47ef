// bench/euler/euler_bench.cpp: one million makeEF/killEF pairs and one million makeEV/killEV
// pairs on a 1000 x 1000 quad grid (10^6 faces): hmira on halfedge_mesh, CGAL Surface_mesh's
// and OpenMesh PolyMesh's native operations, and hmira's generic operators running on CGAL's
// and OpenMesh's own meshes through the interop traits. Each pair restores the mesh, and the
// pairs walk the faces in order, so every variant does the same work on the same faces.
// Every row is cold: a fresh mesh, each pair applied once per face, no warm-up loop (the
// _warm rows are the exception, kept to show what a grown mesh costs).
//
// The pass rows (make_edge_face_pass, kill_edge_face_pass, make_edge_face_repass) apply makeEF
// to every face of a fresh grid in memory order, then killEF to every result, then makeEF
// again, each pass timed on its own: the repass is
// where a model that reuses freed slots (halfedge_mesh, CGAL Surface_mesh) writes into memory
// it already owns, while OpenMesh appends until garbage collection. (The same passes of edge
// splits hung CGAL's split_edge/join_vertex for minutes, so the edge-vertex pair has no pass rows.)
//
// Native equivalents. makeEF/killEF: CGAL::Euler::split_face / join_face; OpenMesh
// insert_edge / remove_edge. makeEV/killEV creates and deletes one vertex and one edge; neither
// library can hang a vertex of degree 1 inside a face with its Euler operations, so the
// closest pair creating and deleting the same elements is an edge split and its undo:
// CGAL::Euler::split_edge / join_vertex, OpenMesh split_edge / collapse.

#include <benchmark/benchmark.h>
#include <sys/resource.h>  // getrusage: the page faults of the timed passes

#include <cstddef>
#include <type_traits>
#include <vector>

#include <hmira/algorithms/euler/make_edge_face.hpp>
#include <hmira/algorithms/euler/make_edge_vertex.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <hmira/interop/cgal.hpp>
#endif
#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <hmira/interop/openmesh.hpp>
#endif

namespace {

constexpr std::size_t grid_n = 1000;    // grid_n^2 quads
constexpr std::size_t pairs = 1000000;  // operator pairs per run

/// Builds the grid through the traits (any mesh_builder).
template <class M, class T = hmira::default_traits<M>>
void build_grid(M& m) {
    using S = typename T::scalar;
    std::vector<typename T::vertex_handle> vs;
    vs.reserve((grid_n + 1) * (grid_n + 1));
    for (std::size_t j = 0; j <= grid_n; ++j)
        for (std::size_t i = 0; i <= grid_n; ++i) vs.push_back(T::add_vertex(m, hmira::vec3<S>{S(i), S(j), S(0)}));
    auto id = [&](std::size_t i, std::size_t j) { return vs[j * (grid_n + 1) + i]; };
    for (std::size_t j = 0; j < grid_n; ++j)
        for (std::size_t i = 0; i < grid_n; ++i) {
            const typename T::vertex_handle q[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
            if (!T::add_face(m, std::span<const typename T::vertex_handle>(q, 4)))
                throw std::runtime_error("grid face refused");
        }
}

/// Per face, the two corners of a diagonal split: h0 and next(next(h0)).
template <class M, class T = hmira::default_traits<M>>
std::vector<std::pair<typename T::halfedge_handle, typename T::halfedge_handle>> split_corners(const M& m) {
    std::vector<std::pair<typename T::halfedge_handle, typename T::halfedge_handle>> out;
    for (auto f : T::faces(m)) {
        const auto h0 = T::face_halfedge(m, f);
        out.push_back({h0, T::next(m, T::next(m, h0))});
    }
    return out;
}

/// Minor page faults of this process so far (first touches of fresh pages).
long minor_faults() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_minflt;
}

/// `faults`: the minor page faults of the timed pairs (a model that grows an array during the
/// pairs pays the first touch of the grown copy, about 2.5 us a 4 KiB page).
template <class M>
void report(benchmark::State& state, long faults) {
    state.counters["pairs"] = static_cast<double>(pairs);
    state.counters["faults"] = static_cast<double>(faults);
    state.counters["ns_per_pair"] = benchmark::Counter(
        static_cast<double>(pairs), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// ----- hmira's generic operators, on any model ------------------------------------------------

/// Without slot reuse halfedge_mesh appends every new element, so a million creations grow its
/// arrays; the _no_reuse rows reserve up front, as a user who knows the count would (what this
/// benchmark measured before halfedge_mesh reused slots). With reuse (the default) a pair
/// allocates nothing and no reserve is needed.
template <class M>
void reserve_for_pairs(M& m) {
    if constexpr (std::is_same_v<M, hmira::halfedge_mesh>)
        if (!m.slot_reuse())
            m.reserve(m.vertex_index_bound() + pairs, m.edge_index_bound() + pairs, m.face_index_bound() + pairs);
}
template <class M>
void set_reuse([[maybe_unused]] M& m, [[maybe_unused]] bool reuse) {
    if constexpr (std::is_same_v<M, hmira::halfedge_mesh>) m.set_slot_reuse(reuse);
}

template <class M, bool Reuse = true>
void hmira_make_kill_edge_face(benchmark::State& state) {
    M m;
    set_reuse(m, Reuse);
    build_grid(m);
    reserve_for_pairs(m);
    const auto corners = split_corners(m);
    const long faults_before = minor_faults();
    for (auto _ : state) {
        for (std::size_t i = 0; i < pairs; ++i) {
            const auto& [h0, h1] = corners[i % corners.size()];
            auto r = hmira::make_edge_face(m, h0, h1);
            auto k = hmira::kill_edge_face(m, r->halfedge);
            benchmark::DoNotOptimize(k);
        }
    }
    report<M>(state, minor_faults() - faults_before);
}

template <class M, bool Reuse = true>
void hmira_make_kill_edge_vertex(benchmark::State& state) {
    using T = hmira::default_traits<M>;
    using S = typename T::scalar;
    M m;
    set_reuse(m, Reuse);
    build_grid(m);
    reserve_for_pairs(m);
    const auto corners = split_corners(m);
    const hmira::vec3<S> p{S(0.5), S(0.5), S(0)};
    const long faults_before = minor_faults();
    for (auto _ : state) {
        for (std::size_t i = 0; i < pairs; ++i) {
            auto r = hmira::make_edge_vertex(m, corners[i % corners.size()].first, p);
            auto k = hmira::kill_edge_vertex(m, r->halfedge);
            benchmark::DoNotOptimize(k);
        }
    }
    report<M>(state, minor_faults() - faults_before);
}

/// The same on halfedge_mesh with slot reuse off, whose arrays were grown once before timing
/// (one untimed run of the pairs, then collect_garbage, which keeps the capacity): it
/// separates the operators' cost from the first touch of the memory an appending model writes
/// new elements into (what the cold rows paid before halfedge_mesh reused slots).
template <class M, bool Face>
void hmira_warm(benchmark::State& state) {
    using T = hmira::default_traits<M>;
    using S = typename T::scalar;
    M m;
    set_reuse(m, false);
    build_grid(m);
    reserve_for_pairs(m);
    const hmira::vec3<S> p{S(0.5), S(0.5), S(0)};
    auto run = [&](const auto& corners) {
        for (std::size_t i = 0; i < pairs; ++i) {
            const auto& [h0, h1] = corners[i % corners.size()];
            if constexpr (Face) {
                auto r = hmira::make_edge_face(m, h0, h1);
                benchmark::DoNotOptimize(hmira::kill_edge_face(m, r->halfedge));
            } else {
                auto r = hmira::make_edge_vertex(m, h0, p);
                benchmark::DoNotOptimize(hmira::kill_edge_vertex(m, r->halfedge));
            }
        }
    };
    run(split_corners(m));
    (void)m.collect_garbage();
    const auto corners = split_corners(m);
    const long faults_before = minor_faults();
    for (auto _ : state) run(corners);
    report<M>(state, minor_faults() - faults_before);
}

BENCHMARK(hmira_warm<hmira::halfedge_mesh, true>)
    ->Name("make_kill_edge_face/hmira_halfedge_mesh_warm")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_warm<hmira::halfedge_mesh, false>)
    ->Name("make_kill_edge_vertex/hmira_halfedge_mesh_warm")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_make_kill_edge_face<hmira::halfedge_mesh>)
    ->Name("make_kill_edge_face/hmira_halfedge_mesh")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_make_kill_edge_vertex<hmira::halfedge_mesh>)
    ->Name("make_kill_edge_vertex/hmira_halfedge_mesh")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_make_kill_edge_face<hmira::halfedge_mesh, false>)
    ->Name("make_kill_edge_face/hmira_halfedge_mesh_no_reuse")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_make_kill_edge_vertex<hmira::halfedge_mesh, false>)
    ->Name("make_kill_edge_vertex/hmira_halfedge_mesh_no_reuse")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

// ----- passes: one operator over every face of a fresh grid, then its inverse, then again ------

/// Which pass a pass benchmark times.
enum class pass { make, kill, remake };

/// Runs `make(i)` for every face i, `kill(result)` for every result (newest first, so that each
/// kill meets the mesh its make left: two splits of one shared edge undo in order), `make`
/// again, and times
/// only the pass asked for (the grid is built untimed, fresh for every repetition).
template <class Make, class Kill>
void timed_passes(benchmark::State& state, pass which, Make make, Kill kill) {
    using R = decltype(make(std::size_t{0}));
    std::vector<R> made;
    made.reserve(grid_n * grid_n);
    // Minor page faults of the timed pass: a cold pass pays the first touch of whatever memory
    // the build left unmapped (hmira's free-slot lists and deleted flags), about 2.5 us a page.
    long faults = 0;
    const auto count = [&](pass p, long before) {
        if (p == which) faults += minor_faults() - before;
    };
    for (auto _ : state) {  // the timer runs at the start and the end of each iteration
        if (which != pass::make) state.PauseTiming();
        long before = minor_faults();
        for (std::size_t i = 0; i < grid_n * grid_n; ++i) made.push_back(make(i));
        count(pass::make, before);
        if (which == pass::make) state.PauseTiming();
        if (which == pass::kill) state.ResumeTiming();
        before = minor_faults();
        for (auto r = made.rbegin(); r != made.rend(); ++r) kill(*r);  // newest first: each undoes its own make
        count(pass::kill, before);
        if (which == pass::kill) state.PauseTiming();
        made.clear();
        if (which == pass::remake) state.ResumeTiming();
        before = minor_faults();
        for (std::size_t i = 0; i < grid_n * grid_n; ++i) made.push_back(make(i));
        count(pass::remake, before);
        if (which != pass::remake) state.ResumeTiming();
    }
    benchmark::DoNotOptimize(made.data());
    state.counters["ops"] = static_cast<double>(grid_n * grid_n);
    state.counters["faults"] = benchmark::Counter(static_cast<double>(faults), benchmark::Counter::kAvgIterations);
}

void hmira_edge_face_passes(benchmark::State& state, pass which) {
    hmira::halfedge_mesh m;
    build_grid(m);
    const auto corners = split_corners(m);
    timed_passes(
        state, which,
        [&](std::size_t i) { return hmira::make_edge_face(m, corners[i].first, corners[i].second)->halfedge; },
        [&](auto h) { benchmark::DoNotOptimize(hmira::kill_edge_face(m, h)); });
}

BENCHMARK_CAPTURE(hmira_edge_face_passes, make, pass::make)
    ->Name("make_edge_face_pass/hmira_halfedge_mesh")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(hmira_edge_face_passes, kill, pass::kill)
    ->Name("kill_edge_face_pass/hmira_halfedge_mesh")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(hmira_edge_face_passes, remake, pass::remake)
    ->Name("make_edge_face_repass/hmira_halfedge_mesh")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;

void cgal_split_join_face(benchmark::State& state) {
    cgal_mesh m;
    build_grid(m);
    const auto corners = split_corners(m);
    const long faults_before = minor_faults();
    for (auto _ : state) {
        for (std::size_t i = 0; i < pairs; ++i) {
            const auto& [h0, h1] = corners[i % corners.size()];
            const auto h = CGAL::Euler::split_face(h0, h1, m);
            benchmark::DoNotOptimize(CGAL::Euler::join_face(h, m));
        }
    }
    report<cgal_mesh>(state, minor_faults() - faults_before);
}

void cgal_split_edge_join_vertex(benchmark::State& state) {
    cgal_mesh m;
    build_grid(m);
    const auto corners = split_corners(m);
    const long faults_before = minor_faults();
    for (auto _ : state) {
        for (std::size_t i = 0; i < pairs; ++i) {
            const auto h = corners[i % corners.size()].first;
            const auto hnew = CGAL::Euler::split_edge(h, m);  // next(hnew) == h, source(h) is new
            benchmark::DoNotOptimize(CGAL::Euler::join_vertex(m.next(hnew), m));
        }
    }
    report<cgal_mesh>(state, minor_faults() - faults_before);
}

void cgal_edge_face_passes(benchmark::State& state, pass which) {
    cgal_mesh m;
    build_grid(m);
    const auto corners = split_corners(m);
    timed_passes(
        state, which, [&](std::size_t i) { return CGAL::Euler::split_face(corners[i].first, corners[i].second, m); },
        [&](auto h) { benchmark::DoNotOptimize(CGAL::Euler::join_face(h, m)); });
}

BENCHMARK_CAPTURE(cgal_edge_face_passes, make, pass::make)
    ->Name("make_edge_face_pass/cgal_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(cgal_edge_face_passes, kill, pass::kill)
    ->Name("kill_edge_face_pass/cgal_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(cgal_edge_face_passes, remake, pass::remake)
    ->Name("make_edge_face_repass/cgal_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(cgal_split_join_face)->Name("make_kill_edge_face/cgal_native")->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_make_kill_edge_face<cgal_mesh>)
    ->Name("make_kill_edge_face/hmira_on_cgal")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(cgal_split_edge_join_vertex)
    ->Name("make_kill_edge_vertex/cgal_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_make_kill_edge_vertex<cgal_mesh>)
    ->Name("make_kill_edge_vertex/hmira_on_cgal")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
#endif

#ifdef HMIRA_BENCH_WITH_OPENMESH
using om_mesh = OpenMesh::PolyMesh_ArrayKernelT<>;

void prepare_status(om_mesh& m) {
    m.request_vertex_status();
    m.request_edge_status();
    m.request_halfedge_status();
    m.request_face_status();
}

void openmesh_insert_remove_edge(benchmark::State& state) {
    om_mesh m;
    build_grid(m);
    prepare_status(m);
    const auto corners = split_corners(m);
    const long faults_before = minor_faults();
    for (auto _ : state) {
        for (std::size_t i = 0; i < pairs; ++i) {
            const auto& [h0, h1] = corners[i % corners.size()];
            // insert_edge joins to(prev) and from(next): the same diagonal as make_edge_face(h0, h1).
            const auto h = m.insert_edge(h0, m.next_halfedge_handle(h1));
            benchmark::DoNotOptimize(m.remove_edge(m.edge_handle(h)));
        }
    }
    report<om_mesh>(state, minor_faults() - faults_before);
}

void openmesh_split_edge_collapse(benchmark::State& state) {
    om_mesh m;
    build_grid(m);
    prepare_status(m);
    const auto corners = split_corners(m);
    const om_mesh::Point p(0.5f, 0.5f, 0.f);
    const long faults_before = minor_faults();
    for (auto _ : state) {
        for (std::size_t i = 0; i < pairs; ++i) {
            const auto h = corners[i % corners.size()].first;
            const auto v = m.add_vertex(p);
            m.split_edge(m.edge_handle(h), v);
            // Collapse the new vertex into its neighbour along one of its two edges.
            m.collapse(m.halfedge_handle(v));
        }
    }
    report<om_mesh>(state, minor_faults() - faults_before);
}

void openmesh_edge_face_passes(benchmark::State& state, pass which) {
    om_mesh m;
    build_grid(m);
    prepare_status(m);
    const auto corners = split_corners(m);
    timed_passes(
        state, which,
        [&](std::size_t i) { return m.insert_edge(corners[i].first, m.next_halfedge_handle(corners[i].second)); },
        [&](auto h) { m.remove_edge(m.edge_handle(h)); });
}

BENCHMARK_CAPTURE(openmesh_edge_face_passes, make, pass::make)
    ->Name("make_edge_face_pass/openmesh_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(openmesh_edge_face_passes, kill, pass::kill)
    ->Name("kill_edge_face_pass/openmesh_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(openmesh_edge_face_passes, remake, pass::remake)
    ->Name("make_edge_face_repass/openmesh_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);

BENCHMARK(openmesh_insert_remove_edge)
    ->Name("make_kill_edge_face/openmesh_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_make_kill_edge_face<om_mesh>)
    ->Name("make_kill_edge_face/hmira_on_openmesh")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(openmesh_split_edge_collapse)
    ->Name("make_kill_edge_vertex/openmesh_native")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(hmira_make_kill_edge_vertex<om_mesh>)
    ->Name("make_kill_edge_vertex/hmira_on_openmesh")
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond);
#endif

}  // namespace

BENCHMARK_MAIN();
