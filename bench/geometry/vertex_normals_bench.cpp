// vertex_normals: hmira's generic version on hmira's meshes and, through the interop traits,
// on OpenMesh's and CGAL's own meshes, against those libraries' native vertex normals on the
// same triangulated torus. Benchmark names are <library>/<mesh>/<variant>/<n> (n x n quads,
// 2 n^2 triangles), so bench/geometry/run.sh can pair them.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <span>
#include <vector>

#include <hmira/algorithms/geometry/vertex_normals.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

#ifdef HMIRA_BENCH_WITH_OPENMESH
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <hmira/interop/openmesh.hpp>
#endif
#ifdef HMIRA_BENCH_WITH_CGAL
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <hmira/interop/cgal.hpp>
#endif

namespace {

struct torus_data {
    std::vector<hmira::vec3<double>> points;
    std::vector<std::array<std::size_t, 3>> triangles;
};

// An n x n torus of quads, each split into two triangles; closed, so every vertex has 6 faces.
torus_data torus(std::size_t n) {
    torus_data t;
    const double R = 2.0, r = 0.7;
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            const double u = 2 * std::numbers::pi * double(i) / double(n),
                         v = 2 * std::numbers::pi * double(j) / double(n);
            t.points.push_back(
                {(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
        }
    auto id = [&](std::size_t i, std::size_t j) { return (i % n) * n + (j % n); };
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            t.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            t.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
        }
    return t;
}

template <class M, class T = hmira::default_traits<M>>
M build(const torus_data& d) {
    using S = typename T::scalar;
    M m;
    std::vector<typename T::vertex_handle> vs;
    for (const auto& p : d.points) vs.push_back(T::add_vertex(m, hmira::vec3<S>{S(p.x), S(p.y), S(p.z)}));
    for (const auto& t : d.triangles) {
        const std::array<typename T::vertex_handle, 3> c{vs[t[0]], vs[t[1]], vs[t[2]]};
        if (!T::add_face(m, std::span<const typename T::vertex_handle>(c)))
            throw std::runtime_error("torus face refused");
    }
    return m;
}

template <class M>
void hmira_normals(benchmark::State& state, hmira::normal_weighting w) {
    const auto mesh = build<M>(torus(static_cast<std::size_t>(state.range(0))));
    for (auto _ : state) {
        auto n = hmira::vertex_normals(mesh, {.weighting = w});
        benchmark::DoNotOptimize(n.data());
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(hmira::default_traits<M>::face_count(mesh)));
}

void sizes(benchmark::internal::Benchmark* b) { b->Arg(128)->Arg(512)->Unit(benchmark::kMillisecond); }

[[maybe_unused]] const auto* const reg_1 =
    benchmark::RegisterBenchmark("hmira/face_vertex_mesh/angle", hmira_normals<hmira::face_vertex_mesh>,
                                 hmira::normal_weighting::angle) -> Apply(sizes);
[[maybe_unused]] const auto* const reg_2 =
    benchmark::RegisterBenchmark("hmira/face_vertex_mesh/area", hmira_normals<hmira::face_vertex_mesh>,
                                 hmira::normal_weighting::area) -> Apply(sizes);
[[maybe_unused]] const auto* const reg_3 = benchmark::RegisterBenchmark(
    "hmira/halfedge_mesh/angle", hmira_normals<hmira::halfedge_mesh>, hmira::normal_weighting::angle) -> Apply(sizes);

#ifdef HMIRA_BENCH_WITH_OPENMESH
using om_mesh = OpenMesh::TriMesh_ArrayKernelT<>;
[[maybe_unused]] const auto* const reg_4 = benchmark::RegisterBenchmark("hmira/openmesh/angle", hmira_normals<om_mesh>,
                                                                        hmira::normal_weighting::angle) -> Apply(sizes);
[[maybe_unused]] const auto* const reg_5 = benchmark::RegisterBenchmark("hmira/openmesh/area", hmira_normals<om_mesh>,
                                                                        hmira::normal_weighting::area) -> Apply(sizes);

// OpenMesh's vertex normals average stored face normals, so a fresh computation is
// update_face_normals() followed by update_vertex_normals() (what update_normals() does).
void openmesh_native(benchmark::State& state, bool include_face_normals) {
    auto mesh = build<om_mesh>(torus(static_cast<std::size_t>(state.range(0))));
    mesh.request_face_normals();
    mesh.request_vertex_normals();
    mesh.update_face_normals();
    for (auto _ : state) {
        if (include_face_normals) mesh.update_face_normals();
        mesh.update_vertex_normals();
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(mesh.n_faces()));
}
[[maybe_unused]] const auto* const reg_6 =
    benchmark::RegisterBenchmark("openmesh/openmesh/face_and_vertex_normals", openmesh_native, true) -> Apply(sizes);
[[maybe_unused]] const auto* const reg_7 =
    benchmark::RegisterBenchmark("openmesh/openmesh/vertex_normals_only", openmesh_native, false) -> Apply(sizes);
#endif

#ifdef HMIRA_BENCH_WITH_CGAL
using cgal_kernel = CGAL::Simple_cartesian<double>;
using cgal_mesh = CGAL::Surface_mesh<cgal_kernel::Point_3>;
[[maybe_unused]] const auto* const reg_8 = benchmark::RegisterBenchmark("hmira/cgal/angle", hmira_normals<cgal_mesh>,
                                                                        hmira::normal_weighting::angle) -> Apply(sizes);
[[maybe_unused]] const auto* const reg_9 = benchmark::RegisterBenchmark("hmira/cgal/area", hmira_normals<cgal_mesh>,
                                                                        hmira::normal_weighting::area) -> Apply(sizes);

void cgal_native(benchmark::State& state) {
    auto mesh = build<cgal_mesh>(torus(static_cast<std::size_t>(state.range(0))));
    auto normals = mesh.add_property_map<cgal_mesh::Vertex_index, cgal_kernel::Vector_3>("v:bench_normal").first;
    for (auto _ : state) {
        CGAL::Polygon_mesh_processing::compute_vertex_normals(mesh, normals);
        benchmark::ClobberMemory();
    }
    state.SetItemsProcessed(state.iterations() * static_cast<long long>(mesh.number_of_faces()));
}
[[maybe_unused]] const auto* const reg_cgal =
    benchmark::RegisterBenchmark("cgal/cgal/compute_vertex_normals", cgal_native) -> Apply(sizes);
#endif

}  // namespace

BENCHMARK_MAIN();
