// The feature table of docs/feature-table.md, proved by compiling every claim: a cell says
// "yes" only if the call compiles for that model (the algorithm's whole body is instantiated,
// not just its requires clause), and the models that can be built also run it on a mesh. The
// test fails when the committed table differs from the one computed here.
//
// Regenerate the file: cmake --build <build> --target feature-table
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include <unistd.h>

#include <hmira/adapters/adapted_mesh.hpp>
#include <hmira/algorithms/delaunay/delaunay_triangulation.hpp>
#include <hmira/algorithms/copy/copy_mesh.hpp>
#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/conversion/voxelize.hpp>
#include <hmira/algorithms/editing/editing.hpp>
#include <hmira/algorithms/euler/euler.hpp>
#include <hmira/algorithms/generators/grid.hpp>
#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/algorithms/generators/torus.hpp>
#include <hmira/algorithms/geometry/vertex_normals.hpp>
#include <hmira/algorithms/orientation/flip_normals.hpp>
#include <hmira/algorithms/holes/fill_hole.hpp>
#include <hmira/algorithms/primitives/primitives.hpp>
#include <hmira/algorithms/remeshing/isotropic_remeshing.hpp>
#include <hmira/algorithms/smoothing/laplacian_smooth.hpp>
#include <hmira/algorithms/boolean/make_solid.hpp>
#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/algorithms/decimation/decimate.hpp>
#include <hmira/algorithms/spatial/aabb_tree.hpp>
#include <hmira/algorithms/spatial/winding_number.hpp>
#include <hmira/algorithms/spatial/bvh.hpp>
#include <hmira/algorithms/spatial/inside_closed.hpp>
#include <hmira/algorithms/validation/self_intersections.hpp>
#include <hmira/algorithms/geometry/mesh_measures.hpp>
#include <hmira/algorithms/subdivision/catmull_clark.hpp>
#include <hmira/algorithms/subdivision/sqrt3.hpp>
#include <hmira/algorithms/subdivision/loop.hpp>
#include <hmira/algorithms/triangle/triangle.hpp>
#include <hmira/algorithms/triangulation/triangulate_faces.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/algorithms/validation/validate.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/io/obj.hpp>
#include <hmira/io/off.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>
#include <hmira/meshes/winged_edge_mesh.hpp>

#include "plain_struct_mesh/plain_mesh.hpp"
#include "trimesh_like/trimesh.hpp"

#if defined(HMIRA_TEST_WITH_OPENMESH) && __has_include(<hmira/interop/openmesh.hpp>)
#include <hmira/interop/openmesh.hpp>
#define HMIRA_TABLE_OPENMESH 1
#endif
#if defined(HMIRA_TEST_WITH_CGAL) && __has_include(<hmira/interop/cgal.hpp>)
#include <CGAL/Simple_cartesian.h>
#include <hmira/interop/cgal.hpp>
#define HMIRA_TABLE_CGAL 1
#endif

namespace {

// ---- the models: one column each ------------------------------------------------------------

template <class M>
struct column;
#define HMIRA_COLUMN(TYPE, TITLE)                   \
    template <>                                     \
    struct column<TYPE> {                           \
        static constexpr const char* title = TITLE; \
    }
HMIRA_COLUMN(hmira::face_vertex_mesh, "face_vertex_mesh");
HMIRA_COLUMN(hmira::halfedge_mesh, "halfedge_mesh");
HMIRA_COLUMN(hmira::winged_edge_mesh, "winged_edge_mesh");
HMIRA_COLUMN(hmira::with_adjacency<hmira::face_vertex_mesh>, "face_vertex_mesh + adapt()");
HMIRA_COLUMN(studio::plain_mesh, "plain struct (examples/plain_struct_mesh)");
HMIRA_COLUMN(lab::trimesh, "Trimesh-like (examples/trimesh_like)");
#ifdef HMIRA_TABLE_OPENMESH
HMIRA_COLUMN(OpenMesh::PolyMesh_ArrayKernelT<>, "OpenMesh PolyMesh");
HMIRA_COLUMN(OpenMesh::TriMesh_ArrayKernelT<>, "OpenMesh TriMesh");
#endif
#ifdef HMIRA_TABLE_CGAL
HMIRA_COLUMN(CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>, "CGAL Surface_mesh");
#endif

template <class... Ms>
struct model_list {};
using models = model_list<hmira::face_vertex_mesh, hmira::halfedge_mesh, hmira::winged_edge_mesh,
                          hmira::with_adjacency<hmira::face_vertex_mesh>, studio::plain_mesh, lab::trimesh
#ifdef HMIRA_TABLE_OPENMESH
                          ,
                          OpenMesh::PolyMesh_ArrayKernelT<>, OpenMesh::TriMesh_ArrayKernelT<>
#endif
#ifdef HMIRA_TABLE_CGAL
                          ,
                          CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>
#endif
                          >;

// ---- the algorithms: one row each -------------------------------------------------------------
// `supported` is the claim; `compile` odr-uses the call in a lambda, so when the claim is "yes"
// the algorithm's body is instantiated for the model here and must compile.

#define HMIRA_ROW(ID, NAME, HEADER, NEEDS, PARAMS, ...)                        \
    struct ID {                                                                \
        static constexpr const char* name = NAME;                              \
        static constexpr const char* header = HEADER;                          \
        static constexpr const char* needs_name = #NEEDS;                      \
        template <class M>                                                     \
        static constexpr bool needs = NEEDS<M>;                                \
        template <class M, class T = hmira::default_traits<M>>                 \
        static constexpr bool supported =                                      \
            requires PARAMS                                                    \
        {                                                                      \
            __VA_ARGS__;                                                       \
        };                                                                     \
        template <class M, class T = hmira::default_traits<M>>                 \
        static void compile() {                                                \
            if constexpr (supported<M, T>) {                                   \
                [[maybe_unused]] auto use = [] PARAMS { return __VA_ARGS__; }; \
            }                                                                  \
        }                                                                      \
    }

using points2 = std::vector<std::array<double, 2>>;
HMIRA_ROW(row_triangle_solids, "generate_tetrahedron, _octahedron, _icosahedron",
          "algorithms/generators/platonic_solids.hpp", hmira::mesh_builder, (M & m),
          hmira::generate_icosahedron<M, T>(m));
HMIRA_ROW(row_polygon_solids, "generate_cube, _dodecahedron", "algorithms/generators/platonic_solids.hpp",
          hmira::polygon_mesh_builder, (M & m), hmira::generate_cube<M, T>(m));
HMIRA_ROW(row_torus, "generate_torus", "algorithms/generators/torus.hpp", hmira::polygon_mesh_builder, (M & m),
          hmira::generate_torus<M, T>(m));
HMIRA_ROW(row_grid, "generate_grid", "algorithms/generators/grid.hpp", hmira::mesh_builder, (M & m),
          hmira::generate_grid<M, T>(m));
HMIRA_ROW(row_validate, "validate", "algorithms/validation/validate.hpp", hmira::validate_mesh, (const M& m),
          hmira::validate<M, T>(m));
HMIRA_ROW(row_topology, "mesh_topology, connected_components, edge_census", "algorithms/topology/mesh_topology.hpp",
          hmira::mesh_topology_mesh, (const M& m), hmira::mesh_topology<M, T>(m));
HMIRA_ROW(row_flip, "flip_normals", "algorithms/orientation/flip_normals.hpp", hmira::flip_normals_mesh, (M & m),
          hmira::flip_normals<M, T>(m));
HMIRA_ROW(row_vertex_normals, "vertex_normals", "algorithms/geometry/vertex_normals.hpp", hmira::vertex_normals_mesh,
          (const M& m), hmira::vertex_normals<M, T>(m));
HMIRA_ROW(row_euler, "Euler operators (make/kill vertex, edge-vertex, edge-face)", "algorithms/euler/euler.hpp",
          hmira::euler_mutable_mesh, (M & m, typename T::halfedge_handle h), hmira::make_edge_face<M, T>(m, h, h));
HMIRA_ROW(row_euler_ring, "Euler ring operators (make/kill face-ring, edge-ring)", "algorithms/euler/euler.hpp",
          hmira::euler_ring_mutable_mesh, (M & m, typename T::halfedge_handle h),
          hmira::make_face_kill_ring<M, T>(m, h));
HMIRA_ROW(row_split_vertex, "split_vertex, join_vertices (general vertex split and its inverse)",
          "algorithms/euler/split_vertex.hpp", hmira::euler_mutable_mesh,
          (M & m, typename T::halfedge_handle h, const hmira::vec3<typename T::scalar>& p),
          hmira::split_vertex<M, T>(m, h, h, p));
HMIRA_ROW(row_add_vertex_face, "add_vertex, add_face (primitives)", "algorithms/primitives/primitives.hpp",
          hmira::mesh_builder, (M & m, const hmira::vec3<typename T::scalar>& p), hmira::add_vertex<M, T>(m, p));
HMIRA_ROW(row_edge_primitives, "add_edge, remove_edge (primitives)", "algorithms/primitives/primitives.hpp",
          hmira::halfedge_mutable_mesh, (M & m, typename T::halfedge_handle h), hmira::remove_edge<M, T>(m, h));
HMIRA_ROW(row_remove_face, "remove_face (primitive)", "algorithms/primitives/primitives.hpp", hmira::face_erasable_mesh,
          (M & m, typename T::face_handle f), hmira::remove_face<M, T>(m, f));
HMIRA_ROW(row_remove_vertex, "remove_vertex (primitive)", "algorithms/primitives/primitives.hpp",
          hmira::vertex_erasable_mesh, (M & m, typename T::vertex_handle v), hmira::remove_vertex<M, T>(m, v));
HMIRA_ROW(row_truncate, "truncate, truncate_all", "algorithms/editing/truncate.hpp", hmira::truncatable_mesh,
          (M & m, typename T::vertex_handle v), hmira::truncate<M, T>(m, v));
HMIRA_ROW(row_bevel, "bevel, bevel_vertices", "algorithms/editing/bevel.hpp", hmira::bevelable_mesh,
          (M & m, typename T::edge_handle e), hmira::bevel<M, T>(m, e));
HMIRA_ROW(row_extrude, "extrude", "algorithms/editing/extrude.hpp", hmira::extrudable_mesh,
          (M & m, typename T::face_handle f), hmira::extrude<M, T>(m, f));
HMIRA_ROW(row_flip_edge, "flip_edge, is_flip_ok", "algorithms/triangle/flip_edge.hpp", hmira::triangle_operable_mesh,
          (M & m, typename T::halfedge_handle h), hmira::flip_edge<M, T>(m, h));
HMIRA_ROW(row_split_edge, "split_edge", "algorithms/triangle/split_edge.hpp", hmira::triangle_operable_mesh,
          (M & m, typename T::halfedge_handle h), hmira::split_edge<M, T>(m, h));
HMIRA_ROW(row_split_face, "split_face", "algorithms/triangle/split_face.hpp", hmira::triangle_operable_mesh,
          (M & m, typename T::face_handle f), hmira::split_face<M, T>(m, f));
HMIRA_ROW(row_collapse_edge, "collapse_edge, is_collapse_ok", "algorithms/triangle/collapse_edge.hpp",
          hmira::triangle_operable_mesh, (M & m, typename T::halfedge_handle h), hmira::collapse_edge<M, T>(m, h));
HMIRA_ROW(row_face_triangles, "face_triangles (one face's triangles, rings included)",
          "algorithms/triangulation/triangulate_faces.hpp", hmira::face_triangulable_mesh,
          (const M& m, typename T::face_handle f), hmira::face_triangles<M, T>(m, f));
HMIRA_ROW(row_triangulate_faces, "triangulate_faces", "algorithms/triangulation/triangulate_faces.hpp",
          hmira::triangulable_mesh, (M & m), hmira::triangulate_faces<M, T>(m));
HMIRA_ROW(row_fill_hole, "fill_hole", "algorithms/holes/fill_hole.hpp", hmira::triangle_operable_mesh,
          (M & m, typename T::halfedge_handle h), hmira::fill_hole<M, T>(m, h));
HMIRA_ROW(row_fill_holes, "fill_holes", "algorithms/holes/fill_hole.hpp", hmira::hole_fillable_mesh, (M & m),
          hmira::fill_holes<M, T>(m, 3));
HMIRA_ROW(row_loop, "loop_subdivide", "algorithms/subdivision/loop.hpp", hmira::loop_subdividable_mesh, (M & m),
          hmira::loop_subdivide<M, T>(m));
HMIRA_ROW(row_sqrt3, "sqrt3_subdivide", "algorithms/subdivision/sqrt3.hpp", hmira::sqrt3_subdividable_mesh, (M & m),
          hmira::sqrt3_subdivide<M, T>(m));
HMIRA_ROW(row_catmull_clark, "catmull_clark_subdivide", "algorithms/subdivision/catmull_clark.hpp",
          hmira::catmull_clark_subdividable_mesh, (M & m), hmira::catmull_clark_subdivide<M, T>(m));
HMIRA_ROW(row_decimate, "decimate (quadric error)", "algorithms/decimation/decimate.hpp", hmira::decimatable_mesh,
          (M & m), hmira::decimate<M, T>(m, {.target_faces = 10}));
HMIRA_ROW(row_smooth, "laplacian_smooth, taubin_smooth", "algorithms/smoothing/laplacian_smooth.hpp",
          hmira::smoothable_mesh, (M & m), hmira::taubin_smooth<M, T>(m));
HMIRA_ROW(row_remesh, "isotropic_remeshing", "algorithms/remeshing/isotropic_remeshing.hpp", hmira::remeshable_mesh,
          (M & m), hmira::isotropic_remeshing<M, T>(m, {.target_edge_length = 1}));
HMIRA_ROW(row_copy_from, "copy_mesh (from this model, e.g. into halfedge_mesh)", "algorithms/copy/copy_mesh.hpp",
          hmira::copy_source_mesh, (const M& m, hmira::halfedge_mesh& h),
          hmira::copy_mesh<M, hmira::halfedge_mesh, T>(m, h));
HMIRA_ROW(row_copy_into, "copy_mesh (into this model, e.g. from halfedge_mesh)", "algorithms/copy/copy_mesh.hpp",
          hmira::copy_target_mesh, (M & m, const hmira::halfedge_mesh& h),
          hmira::copy_mesh<hmira::halfedge_mesh, M, hmira::default_traits<hmira::halfedge_mesh>, T>(h, m));
HMIRA_ROW(row_aabb_tree, "aabb_tree_from_mesh (closest_point, ray_intersect)", "algorithms/spatial/aabb_tree.hpp",
          hmira::aabb_tree_source_mesh, (const M& m), hmira::aabb_tree_from_mesh<M, T>(m));
HMIRA_ROW(row_surface_queries,
          "winding_number, contains, signed_distance, signed_distance_grid, offset, sample_surface, hausdorff_distance",
          "algorithms/spatial/winding_number.hpp (and signed_distance, signed_distance_grid, sample_surface, "
          "hausdorff_distance)",
          hmira::surface_query_mesh, (const M& m, std::span<const hmira::vec3<double>> p),
          hmira::winding_number<M, T>(m, p));
HMIRA_ROW(row_bvh, "build_bvh, refit_bvh (closest_point(s), first/any/all ray hits)", "algorithms/spatial/bvh.hpp",
          hmira::bvh_source_mesh, (const M& m), hmira::build_bvh<M, T>(m));
HMIRA_ROW(row_inside_closed, "inside_closed, closed_winding_number (exact)", "algorithms/spatial/inside_closed.hpp",
          hmira::inside_closed_mesh, (const M& m, std::span<const hmira::vec3<double>> p),
          hmira::inside_closed<M, T>(m, p));
HMIRA_ROW(row_self_intersections, "self_intersections (exact)", "algorithms/validation/self_intersections.hpp",
          hmira::self_intersection_mesh, (const M& m), hmira::self_intersections<M, T>(m));
HMIRA_ROW(row_boolean, "mesh_boolean (exact; from this model, e.g. into halfedge_mesh)",
          "algorithms/boolean/mesh_boolean.hpp", hmira::boolean_input_mesh, (const M& a, hmira::halfedge_mesh& out),
          hmira::mesh_boolean<hmira::halfedge_mesh, M, M>(out, a, a));
HMIRA_ROW(row_make_solid, "make_solid (exact; from this model, e.g. into halfedge_mesh)",
          "algorithms/boolean/make_solid.hpp", hmira::boolean_input_mesh, (const M& a, hmira::halfedge_mesh& out),
          hmira::make_solid<hmira::halfedge_mesh, M>(out, a));
HMIRA_ROW(row_measures, "surface_area, signed_volume", "algorithms/geometry/mesh_measures.hpp", hmira::face_normal_mesh,
          (const M& m), hmira::signed_volume<M, T>(m));
HMIRA_ROW(row_marching_cubes, "marching_cubes (into the mesh)", "algorithms/conversion/marching_cubes.hpp",
          hmira::mesh_builder, (M & m, const hmira::dense_grid<float>& g), hmira::marching_cubes<M, T>(m, g));
HMIRA_ROW(row_voxelize, "voxelize", "algorithms/conversion/voxelize.hpp", hmira::voxelize_mesh,
          (const M& m, const hmira::grid_geometry& g), hmira::voxelize<M, T>(m, g));
HMIRA_ROW(row_delaunay, "delaunay_triangulation (into the mesh)", "algorithms/delaunay/delaunay_triangulation.hpp",
          hmira::mesh_builder, (M & m, const points2& p), hmira::delaunay_triangulation<M, T>(m, p));
HMIRA_ROW(row_read, "read_obj, read_off", "io/obj.hpp, io/off.hpp", hmira::io::readable_mesh,
          (M & m, const std::filesystem::path& p), hmira::io::read_obj<M, T>(m, p));
HMIRA_ROW(row_write, "write_obj, write_off", "io/obj.hpp, io/off.hpp", hmira::io::writable_mesh,
          (const M& m, const std::filesystem::path& p), hmira::io::write_obj<M, T>(m, p));
HMIRA_ROW(row_adapt_brute, "adapt_brute_force (adjacency by scanning faces)", "adapters/adapted_mesh.hpp",
          hmira::adapter_source_mesh, (M & m), hmira::adapt_brute_force<M, T>(m));
HMIRA_ROW(row_adapt_indexed, "adapt, adapt_indexed (adjacency from an index)", "adapters/adapted_mesh.hpp",
          hmira::indexed_adapter_source_mesh, (M & m), hmira::adapt_indexed<M, T>(m));

template <class... Rs>
struct row_list {};
using rows =
    row_list<row_triangle_solids, row_polygon_solids, row_torus, row_grid, row_validate, row_topology, row_flip,
             row_vertex_normals, row_euler, row_euler_ring, row_split_vertex, row_add_vertex_face, row_edge_primitives,
             row_remove_face, row_remove_vertex, row_truncate, row_bevel, row_extrude, row_flip_edge, row_split_edge,
             row_split_face, row_collapse_edge, row_face_triangles, row_triangulate_faces, row_fill_hole,
             row_fill_holes, row_loop, row_sqrt3, row_catmull_clark, row_decimate, row_smooth, row_remesh,
             row_copy_from, row_copy_into, row_aabb_tree, row_surface_queries, row_bvh, row_inside_closed,
             row_self_intersections, row_boolean, row_make_solid, row_measures, row_marching_cubes, row_voxelize,
             row_delaunay, row_read, row_write, row_adapt_brute, row_adapt_indexed>;

// ---- the capabilities of concepts.hpp: one row each -------------------------------------------

#define HMIRA_CAPABILITY(NAME)                            \
    struct cap_##NAME {                                   \
        static constexpr const char* name = #NAME;        \
        template <class M>                                \
        static constexpr bool supported = hmira::NAME<M>; \
    }
HMIRA_CAPABILITY(mesh_element_types);
HMIRA_CAPABILITY(vertex_list_mesh);
HMIRA_CAPABILITY(face_list_mesh);
HMIRA_CAPABILITY(edge_list_mesh);
HMIRA_CAPABILITY(vertex_index_mesh);
HMIRA_CAPABILITY(face_index_mesh);
HMIRA_CAPABILITY(edge_index_mesh);
HMIRA_CAPABILITY(face_vertex_range_mesh);
HMIRA_CAPABILITY(positioned_mesh);
HMIRA_CAPABILITY(position_mutable_mesh);
HMIRA_CAPABILITY(vertex_adjacency_mesh);
HMIRA_CAPABILITY(vertex_face_adjacency_mesh);
HMIRA_CAPABILITY(vertex_edge_adjacency_mesh);
HMIRA_CAPABILITY(face_adjacency_mesh);
HMIRA_CAPABILITY(halfedge_navigable_mesh);
HMIRA_CAPABILITY(halfedge_index_mesh);
HMIRA_CAPABILITY(inner_ring_mesh);
HMIRA_CAPABILITY(mesh_builder);
HMIRA_CAPABILITY(polygon_mesh_builder);
HMIRA_CAPABILITY(face_reversible_mesh);
HMIRA_CAPABILITY(halfedge_mutable_mesh);
HMIRA_CAPABILITY(inner_ring_mutable_mesh);
HMIRA_CAPABILITY(face_removal_mesh);
HMIRA_CAPABILITY(vertex_removal_mesh);
HMIRA_CAPABILITY(change_counted_mesh);
HMIRA_CAPABILITY(reservable_mesh);
HMIRA_CAPABILITY(bulk_growable_mesh);
HMIRA_CAPABILITY(orientation_reversible_mesh);
HMIRA_CAPABILITY(erase_preparing_mesh);
HMIRA_CAPABILITY(bulk_vertex_removal_mesh);
HMIRA_CAPABILITY(vertex_halfedge_restorable_mesh);
HMIRA_CAPABILITY(triangle_only_mesh);
// Two hooks whose concepts take other parameters: the vertex handle, and the traits alone.
struct cap_removal_queryable_mesh {
    static constexpr const char* name = "removal_queryable_mesh";
    template <class M>
    static constexpr bool supported =
        hmira::removal_queryable_mesh<M, hmira::default_traits<M>, typename hmira::default_traits<M>::vertex_handle>;
};
struct cap_fault_injecting_traits {
    static constexpr const char* name = "fault_injecting_traits";
    template <class M>
    static constexpr bool supported = hmira::fault_injecting_traits<hmira::default_traits<M>>;
};
using capabilities =
    row_list<cap_mesh_element_types, cap_vertex_list_mesh, cap_face_list_mesh, cap_edge_list_mesh,
             cap_vertex_index_mesh, cap_face_index_mesh, cap_edge_index_mesh, cap_face_vertex_range_mesh,
             cap_positioned_mesh, cap_position_mutable_mesh, cap_vertex_adjacency_mesh, cap_vertex_face_adjacency_mesh,
             cap_vertex_edge_adjacency_mesh, cap_face_adjacency_mesh, cap_halfedge_navigable_mesh,
             cap_halfedge_index_mesh, cap_inner_ring_mesh, cap_mesh_builder, cap_polygon_mesh_builder,
             cap_face_reversible_mesh, cap_halfedge_mutable_mesh, cap_inner_ring_mutable_mesh, cap_face_removal_mesh,
             cap_vertex_removal_mesh, cap_change_counted_mesh, cap_reservable_mesh, cap_bulk_growable_mesh,
             cap_orientation_reversible_mesh, cap_erase_preparing_mesh, cap_bulk_vertex_removal_mesh,
             cap_vertex_halfedge_restorable_mesh, cap_removal_queryable_mesh, cap_triangle_only_mesh,
             cap_fault_injecting_traits>;

// A few claims spelled out, so that the compiler states them even before the table is read.
static_assert(!hmira::vertex_adjacency_mesh<hmira::face_vertex_mesh>);
static_assert(hmira::vertex_adjacency_mesh<hmira::with_adjacency<hmira::face_vertex_mesh>>);
static_assert(hmira::face_adjacency_mesh<lab::trimesh> && !hmira::face_adjacency_mesh<studio::plain_mesh>);
static_assert(row_vertex_normals::supported<studio::plain_mesh> && row_vertex_normals::supported<lab::trimesh>);
static_assert(!row_polygon_solids::supported<lab::trimesh>, "a triangles-only model refuses quads");
static_assert(!row_euler::supported<hmira::face_vertex_mesh> && row_euler::supported<hmira::halfedge_mesh>);
static_assert(row_adapt_brute::supported<studio::plain_mesh> && !row_adapt_indexed::supported<studio::plain_mesh>,
              "indexed adapters need change_count, which a plain struct lacks");

// ---- rendering --------------------------------------------------------------------------------

using table = std::map<std::string, std::map<std::string, std::string>>;  // row -> column -> cell

template <class... Ms>
std::vector<std::string> column_titles(model_list<Ms...>) {
    return {column<Ms>::title...};
}

template <class R, class... Ms>
void fill_row(table& t, std::vector<std::string>& order, model_list<Ms...>) {
    order.push_back(R::name);
    ((t[R::name][column<Ms>::title] = R::template supported<Ms> ? "yes" : "no"), ...);
}
template <class... Rs>
void fill(table& t, std::vector<std::string>& order, row_list<Rs...>) {
    (fill_row<Rs>(t, order, models{}), ...);
}

template <class R, class... Ms>
void compile_row(model_list<Ms...>) {
    (R::template compile<Ms>(), ...);
}
template <class... Rs>
void compile_all(row_list<Rs...>) {
    (compile_row<Rs>(models{}), ...);
}

std::string header_of(const std::string& row) {
    std::string out;
    [&]<class... Rs>(row_list<Rs...>) { ((row == Rs::name ? void(out = Rs::header) : void()), ...); }(rows{});
    return out;
}

// The algorithm's concept as a reader would look it up: without the namespace.
std::string needs_of(const std::string& row) {
    std::string out;
    [&]<class... Rs>(row_list<Rs...>) { ((row == Rs::name ? void(out = Rs::needs_name) : void()), ...); }(rows{});
    return out.substr(out.rfind(':') + 1);
}

template <class R, class... Ms>
constexpr bool needs_agree(model_list<Ms...>) {
    return ((R::template supported<Ms> == R::template needs<Ms>)&&...);
}
// Each row's concept is the whole truth about it: the call compiles exactly where it holds.
static_assert([]<class... Rs>(row_list<Rs...>) { return (needs_agree<Rs>(models{}) && ...); }(rows{}),
              "a row's `needs` concept disagrees with whether its call compiles");

std::string render() {
    const auto cols = column_titles(models{});
    std::ostringstream s;
    s << "<!-- Generated by tests/docs/feature_table_test.cpp; do not edit by hand.\n"
         "     Regenerate: cmake --build <build dir> --target feature-table -->\n"
         "# What runs on which model\n\n"
         "Every \"yes\" below was compiled: the test instantiates the algorithm for that model, and\n"
         "runs it on a small mesh for the models that can be built empty. Every \"no\" is a call that\n"
         "the algorithm's requires clause rejects, with a message naming the missing capability.\n"
         "A \"no\" for face-vertex models is what adapters are for: see the `face_vertex_mesh + adapt()`\n"
         "column and [docs/own-mesh.md](own-mesh.md). The \"needs\" column is the algorithm's concept\n"
         "(the test checks that the call compiles exactly where it holds); [docs/concepts.md](concepts.md)\n"
         "says what each one asks your traits for. Headers are under `include/hmira/`.\n\n";
    auto emit = [&](const char* title, const table& t, const std::vector<std::string>& order, bool with_header) {
        s << "## " << title << "\n\n| |";
        if (with_header) s << " needs | header |";
        for (const auto& c : cols) s << ' ' << c << " |";
        s << "\n|---|";
        if (with_header) s << "---|---|";
        for (std::size_t i = 0; i < cols.size(); ++i) s << ":---:|";
        s << '\n';
        for (const auto& r : order) {
            s << "| " << (with_header ? r : "`" + r + "`") << " |";
            if (with_header) s << " `" << needs_of(r) << "` | `" << header_of(r) << "` |";
            for (const auto& c : cols) s << ' ' << t.at(r).at(c) << " |";
            s << '\n';
        }
        s << '\n';
    };
    table algorithms, caps;
    std::vector<std::string> algorithm_order, cap_order;
    fill(algorithms, algorithm_order, rows{});
    fill(caps, cap_order, capabilities{});
    emit("Algorithms", algorithms, algorithm_order, true);
    emit("Capabilities (the concepts of include/hmira/concepts.hpp, see docs/concepts.md)", caps, cap_order, false);
    return s.str();
}

// Parses the tables of a feature-table file: section -> row -> column -> cell.
std::map<std::string, table> parse(const std::string& text) {
    std::map<std::string, table> out;
    std::istringstream in(text);
    std::string line, section;
    std::vector<std::string> header;
    auto cells = [](const std::string& l) {
        std::vector<std::string> c;
        std::string cur;
        for (std::size_t i = 1; i < l.size(); ++i) {
            if (l[i] == '|') {
                const auto b = cur.find_first_not_of(' '), e = cur.find_last_not_of(' ');
                c.push_back(b == std::string::npos ? "" : cur.substr(b, e - b + 1));
                cur.clear();
            } else {
                cur += l[i];
            }
        }
        return c;
    };
    while (std::getline(in, line)) {
        if (line.rfind("## ", 0) == 0) {
            section = line.substr(3);
            header.clear();
        } else if (line.rfind("|", 0) == 0) {
            auto c = cells(line);
            if (header.empty())
                header = c;
            else if (!c.empty() && c[0].rfind("---", 0) != 0)
                for (std::size_t i = 1; i < c.size() && i < header.size(); ++i) out[section][c[0]][header[i]] = c[i];
        }
    }
    return out;
}

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

const std::filesystem::path table_path = std::filesystem::path(HMIRA_SOURCE_DIR) / "docs" / "feature-table.md";

TEST(feature_table, every_yes_compiles_for_its_model) {
    compile_all(rows{});  // the instantiations happen at compile time; reaching here is the proof
    SUCCEED();
}

// Runs the whole-mesh rows on every model that can be built empty, checking each answer.
template <class M>
void run_claims() {
    using T = hmira::default_traits<M>;
    M mesh;
    ASSERT_TRUE(hmira::generate_icosahedron(mesh));
    if constexpr (row_validate::supported<M>) {
        EXPECT_TRUE(hmira::validate(mesh).empty()) << column<M>::title;
    }
    if constexpr (row_topology::supported<M>) {
        EXPECT_EQ(hmira::mesh_topology(mesh).euler_characteristic, 2) << column<M>::title;
    }
    if constexpr (row_vertex_normals::supported<M>) {
        EXPECT_EQ(hmira::vertex_normals(mesh).size(), T::vertex_index_bound(mesh)) << column<M>::title;
    }
    if constexpr (row_flip::supported<M>) {
        EXPECT_EQ(hmira::flip_normals(mesh), 20u) << column<M>::title;
        if constexpr (row_validate::supported<M>) {
            EXPECT_TRUE(hmira::validate(mesh).empty()) << column<M>::title;
        }
    }
    if constexpr (row_adapt_brute::supported<M>) {
        const auto a = hmira::adapt_brute_force(mesh);
        for (auto v : T::vertices(mesh)) {
            EXPECT_EQ(std::ranges::distance(hmira::default_traits<decltype(a)>::adjacent_vertices(a, v)), 5)
                << column<M>::title;
            break;
        }
    }
    if constexpr (row_polygon_solids::supported<M>) {
        M cube;
        ASSERT_TRUE(hmira::generate_cube(cube)) << column<M>::title;
        EXPECT_EQ(T::face_count(cube), 6u);
    }
    if constexpr (row_grid::supported<M>) {
        M grid;
        EXPECT_TRUE(hmira::generate_grid(grid, {.triangles = !hmira::polygon_mesh_builder<M>})) << column<M>::title;
    }
}

template <class M, class T = hmira::default_traits<M>>
M icosahedron() {
    M m;
    EXPECT_TRUE(hmira::generate_icosahedron(m));
    return m;
}

template <class M, class T = hmira::default_traits<M>>
::testing::AssertionResult valid_closed(const M& m) {
    const auto problems = hmira::validate(m);
    if (!problems.empty()) return ::testing::AssertionFailure() << column<M>::title << ": " << problems.front().message;
    const auto chi = hmira::mesh_topology(m).euler_characteristic;
    if (chi != 2)
        return ::testing::AssertionFailure() << column<M>::title << ": Euler characteristic " << chi << ", expected 2";
    return ::testing::AssertionSuccess();
}

// The editing, Euler and primitive rows, run on an icosahedron (V 12, E 30, F 20) for every
// model that claims them; every mutation is validated.
template <class M>
void run_editing_claims() {
    using T = hmira::default_traits<M>;
    const auto first_vertex = [](const M& m) {
        auto all = T::vertices(m);
        return *all.begin();
    };
    const auto first_face = [](const M& m) {
        auto all = T::faces(m);
        return *all.begin();
    };
    if constexpr (row_split_vertex::supported<M>) {
        auto m = icosahedron<M>();
        auto split = hmira::split_vertex(m, T::face_halfedge(m, first_face(m)), T::face_halfedge(m, first_face(m)),
                                         {0.1, 0.1, 0.1});
        ASSERT_TRUE(split) << column<M>::title << ": " << split.error().message;
        EXPECT_EQ(T::vertex_count(m), 13u) << column<M>::title;
        auto join = hmira::join_vertices(m, split->halfedge);
        ASSERT_TRUE(join) << column<M>::title << ": " << join.error().message;
        EXPECT_EQ(T::vertex_count(m), 12u) << column<M>::title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_add_vertex_face::supported<M>) {
        auto m = icosahedron<M>();
        hmira::add_vertex(m, {5, 5, 5});
        EXPECT_EQ(T::vertex_count(m), 13u) << column<M>::title;
    }
    if constexpr (row_remove_vertex::supported<M>) {
        // Five faces and the vertex; on a model with edges, its five spokes too.
        auto m = icosahedron<M>();
        auto r = hmira::remove_vertex(m, first_vertex(m));
        ASSERT_TRUE(r) << column<M>::title << ": " << r.error().message;
        EXPECT_EQ(r->faces, 5u) << column<M>::title;
        EXPECT_EQ(r->edges, hmira::halfedge_mutable_mesh<M> ? 5u : 0u) << column<M>::title;
        EXPECT_EQ(r->vertices, 1u) << column<M>::title;
        EXPECT_EQ(T::face_count(m), 15u) << column<M>::title;
        EXPECT_TRUE(hmira::validate(m).empty()) << column<M>::title;
    }
    if constexpr (row_remove_face::supported<M> && row_add_vertex_face::supported<M>) {
        auto m = icosahedron<M>();
        const auto f = first_face(m);
        std::vector<typename T::vertex_handle> corners;
        for (auto v : T::face_vertices(m, f)) corners.push_back(v);
        auto r = hmira::remove_face(m, f);
        ASSERT_TRUE(r) << column<M>::title << ": " << r.error().message;
        EXPECT_EQ(T::face_count(m), 19u) << column<M>::title;
        EXPECT_TRUE(hmira::validate(m).empty()) << column<M>::title;
        ASSERT_TRUE(hmira::add_face(m, std::span<const typename T::vertex_handle>(corners))) << column<M>::title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_edge_primitives::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::remove_edge(m, T::face_halfedge(m, first_face(m)));
        ASSERT_TRUE(r) << column<M>::title << ": " << r.error().message;
        EXPECT_EQ(T::face_count(m), 18u) << column<M>::title;
        EXPECT_TRUE(hmira::validate(m).empty()) << column<M>::title;
        // Every vertex of a closed mesh is interior: a wire edge there is refused.
        auto closed = icosahedron<M>();
        const auto h = T::face_halfedge(closed, first_face(closed));
        EXPECT_FALSE(
            hmira::add_edge(closed, T::target(closed, h), T::target(closed, T::next(closed, T::next(closed, h)))));
    }
    if constexpr (row_truncate::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::truncate(m, first_vertex(m));
        ASSERT_TRUE(r) << column<M>::title << ": " << r.error().message;
        EXPECT_EQ(T::vertex_count(m), 16u) << column<M>::title;  // one corner becomes five
        EXPECT_EQ(T::face_count(m), 21u) << column<M>::title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_bevel::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::bevel(m, T::edge(m, T::face_halfedge(m, first_face(m))));
        ASSERT_TRUE(r) << column<M>::title << ": " << r.error().message;
        EXPECT_EQ(r->strip_faces.size(), 1u) << column<M>::title;
        EXPECT_GT(T::face_count(m), 20u) << column<M>::title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_extrude::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::extrude(m, first_face(m));
        ASSERT_TRUE(r) << column<M>::title << ": " << r.error().message;
        EXPECT_EQ(r->side_faces.size(), 3u) << column<M>::title;
        EXPECT_EQ(T::vertex_count(m), 15u) << column<M>::title;
        EXPECT_EQ(T::face_count(m), 23u) << column<M>::title;
        EXPECT_TRUE(valid_closed(m));
    }
}

using counts_t = std::array<std::size_t, 3>;
template <class M, class T = hmira::default_traits<M>>
auto first_halfedge_of(const M& m) {
    return T::face_halfedge(m, *T::faces(m).begin());
}
template <class M, class T = hmira::default_traits<M>>
counts_t vef_counts(const M& m) {
    return {T::vertex_count(m), T::edge_count(m), T::face_count(m)};
}

// The triangle operators, triangulation, hole filling, subdivision and smoothing rows, run on an
// icosahedron (V 12, E 30, F 20) for every model that claims them; every mutation is validated.
template <class M>
void run_everyday_claims() {
    using T = hmira::default_traits<M>;
    const std::string title = column<M>::title;
    const auto first_face = [](const M& m) { return *T::faces(m).begin(); };
    if constexpr (row_flip_edge::supported<M>) {
        auto m = icosahedron<M>();
        EXPECT_TRUE(hmira::is_flip_ok(m, first_halfedge_of(m))) << title;
        auto r = hmira::flip_edge(m, first_halfedge_of(m));
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_TRUE(valid_closed(m));
        EXPECT_EQ(vef_counts(m), (counts_t{12, 30, 20})) << title;
        ASSERT_TRUE(hmira::flip_edge(m, r->halfedge)) << title;  // its own inverse
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_split_edge::supported<M> && row_collapse_edge::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::split_edge(m, first_halfedge_of(m));
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(vef_counts(m), (counts_t{13, 33, 22})) << title;  // one vertex, both triangles cut
        EXPECT_TRUE(valid_closed(m));
        EXPECT_TRUE(hmira::is_collapse_ok(m, r->halfedge)) << title;
        auto c = hmira::collapse_edge(m, r->halfedge);  // the inverse
        ASSERT_TRUE(c) << title << ": " << c.error().message;
        EXPECT_EQ(vef_counts(m), (counts_t{12, 30, 20})) << title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_split_face::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::split_face(m, first_face(m));
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(vef_counts(m), (counts_t{13, 33, 22})) << title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_face_triangles::supported<M>) {
        const auto m = icosahedron<M>();
        auto r = hmira::face_triangles(m, first_face(m));
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(r->size(), 1u) << title;
    }
    if constexpr (row_triangulate_faces::supported<M> && row_polygon_solids::supported<M>) {
        M cube;
        ASSERT_TRUE(hmira::generate_cube(cube)) << title;
        auto r = hmira::triangulate_faces(cube);
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(r->faces_cut, 6u) << title;
        EXPECT_EQ(vef_counts(cube), (counts_t{8, 18, 12})) << title;
        EXPECT_TRUE(valid_closed(cube));
    }
    if constexpr (row_fill_hole::supported<M> && row_remove_face::supported<M>) {
        auto m = icosahedron<M>();
        const auto h = first_halfedge_of(m);
        ASSERT_TRUE(hmira::remove_face(m, first_face(m))) << title;
        EXPECT_TRUE(hmira::validate(m).empty()) << title;
        auto r = hmira::fill_hole(m, h);  // h now borders the hole
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(r->faces.size(), 1u) << title;
        EXPECT_EQ(vef_counts(m), (counts_t{12, 30, 20})) << title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_fill_holes::supported<M> && row_remove_face::supported<M>) {
        auto m = icosahedron<M>();
        ASSERT_TRUE(hmira::remove_face(m, first_face(m))) << title;
        auto r = hmira::fill_holes(m, 3);
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(r->filled, 1u) << title;
        EXPECT_EQ(r->faces_added, 1u) << title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_loop::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::loop_subdivide(m);
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(vef_counts(m), (counts_t{42, 120, 80})) << title;  // V + E, 2E + 3F, 4F
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_sqrt3::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::sqrt3_subdivide(m);
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(vef_counts(m), (counts_t{32, 90, 60})) << title;  // V + F, E + 3F, 3F
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_catmull_clark::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::catmull_clark_subdivide(m);
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(vef_counts(m), (counts_t{62, 120, 60})) << title;  // V + E + F, 2E + 3F, 3F
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_decimate::supported<M>) {
        auto m = icosahedron<M>();
        auto r = hmira::decimate(m, {.target_faces = 16});
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(vef_counts(m), (counts_t{10, 24, 16})) << title;  // two collapses, each -1 V, -3 E, -2 F
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_smooth::supported<M>) {
        // The icosahedron's vertices lie on one sphere; a uniform Laplacian step pulls each one
        // inward, and Taubin's inflating step brings most of it back.
        const auto radius = [](const M& m) {
            double r = 0;
            for (auto v : T::vertices(m)) {
                const auto p = T::position(m, v);
                r += std::sqrt(double(p[0]) * double(p[0]) + double(p[1]) * double(p[1]) + double(p[2]) * double(p[2]));
            }
            return r / double(T::vertex_count(m));
        };
        auto m = icosahedron<M>();
        const double r0 = radius(m);
        auto l = hmira::laplacian_smooth(m);
        ASSERT_TRUE(l) << title << ": " << l.error().message;
        EXPECT_EQ(l->moved, 12u) << title;
        EXPECT_LT(radius(m), 0.9 * r0) << title;
        EXPECT_TRUE(valid_closed(m));
        auto t = icosahedron<M>();
        auto r = hmira::taubin_smooth(t, {.iterations = 1});
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_GT(radius(t), 0.9 * r0) << title;  // 0.724 after the lambda step, 0.936 after mu
        EXPECT_LT(radius(t), r0) << title;
        EXPECT_TRUE(valid_closed(t));
    }
    if constexpr (row_remesh::supported<M>) {
        // The icosahedron's edges are about 1.05 long; a target of 0.5 splits them all.
        auto m = icosahedron<M>();
        auto r = hmira::isotropic_remeshing(m, {.target_edge_length = 0.5, .iterations = 2});
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_GT(T::face_count(m), 20u) << title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_copy_from::supported<M> && row_copy_into::supported<M>) {
        // Into a half-edge mesh, decimated there, and back: the way a face list runs decimate.
        auto m = icosahedron<M>();
        hmira::halfedge_mesh h;
        auto in = hmira::copy_mesh(m, h);
        ASSERT_TRUE(in) << title << ": " << in.error().message;
        EXPECT_EQ(vef_counts(h), (counts_t{12, 30, 20})) << title;
        ASSERT_TRUE(hmira::decimate(h, {.target_faces = 16})) << title;
        auto out = hmira::copy_mesh(h, m);
        ASSERT_TRUE(out) << title << ": " << out.error().message;
        EXPECT_EQ(T::vertex_count(m), 10u) << title;
        EXPECT_EQ(T::face_count(m), 16u) << title;
        EXPECT_TRUE(valid_closed(m));
    } else if constexpr (row_copy_from::supported<M>) {
        const auto m = icosahedron<M>();
        hmira::halfedge_mesh h;
        auto in = hmira::copy_mesh(m, h);
        ASSERT_TRUE(in) << title << ": " << in.error().message;
        EXPECT_EQ(vef_counts(h), (counts_t{12, 30, 20})) << title;
    }
    if constexpr (row_aabb_tree::supported<M>) {
        auto m = icosahedron<M>();
        auto tree = hmira::aabb_tree_from_mesh(m);
        ASSERT_TRUE(tree) << title;
        EXPECT_EQ(tree->size(), 20u) << title;
        // A vertex is on the surface; the centre is inside, nearer a face than any vertex.
        const auto p = T::position(m, *T::vertices(m).begin());
        const hmira::vec3<double> corner{double(p[0]), double(p[1]), double(p[2])};
        EXPECT_EQ(tree->closest_point(corner).distance, 0.0) << title;
        const double centre = tree->closest_point({0, 0, 0}).distance;
        EXPECT_GT(centre, 0.5 * hmira::norm(corner)) << title;
        EXPECT_LT(centre, hmira::norm(corner)) << title;
    }
    if constexpr (row_bvh::supported<M>) {
        auto m = icosahedron<M>();
        auto tree = hmira::build_bvh(m);
        ASSERT_TRUE(tree) << title << ": " << tree.error().message;
        auto c = hmira::closest_point(m, *tree, hmira::vec3<double>{0, 0, 0});
        ASSERT_TRUE(c) << title << ": " << c.error().message;
        EXPECT_GT(c->distance, 0.5) << title;  // the origin is inside, away from every face
    }
    if constexpr (row_inside_closed::supported<M>) {
        auto m = icosahedron<M>();
        const std::vector<hmira::vec3<double>> p{{0, 0, 0}, {5, 5, 5}};
        auto where = hmira::inside_closed(m, std::span<const hmira::vec3<double>>(p));
        ASSERT_TRUE(where) << title << ": " << where.error().message;
        EXPECT_EQ((*where)[0], hmira::point_location::inside) << title;
        EXPECT_EQ((*where)[1], hmira::point_location::outside) << title;
    }
    if constexpr (row_self_intersections::supported<M>) {
        auto pairs = hmira::self_intersections(icosahedron<M>());
        ASSERT_TRUE(pairs) << title << ": " << pairs.error().message;
        EXPECT_TRUE(pairs->empty()) << title;
    }
    if constexpr (row_boolean::supported<M>) {
        // This model's icosahedron against a halfedge_mesh one moved off-centre: the volume identity.
        const auto a = icosahedron<M>();
        auto b = icosahedron<hmira::halfedge_mesh>();
        for (auto v : b.vertices()) b.set_position(v, b.position(v) + hmira::vec3<double>{0.31, 0.17, 0.13});
        double volume[2] = {};
        for (auto [i, op] : {std::pair{0, hmira::boolean_op::union_}, std::pair{1, hmira::boolean_op::intersection}}) {
            hmira::halfedge_mesh out;
            auto r = hmira::mesh_boolean(out, a, b, {.op = op});
            ASSERT_TRUE(r) << title << ": " << r.error().message;
            EXPECT_GT(r->cut_triangles, 0u) << title;
            volume[i] = hmira::signed_volume(out);
        }
        EXPECT_NEAR(volume[0] + volume[1], hmira::signed_volume(a) + hmira::signed_volume(b), 1e-9) << title;
        EXPECT_GT(volume[1], 0.1 * hmira::signed_volume(b)) << title;
    }
    if constexpr (row_make_solid::supported<M>) {
        // This model's icosahedron is already a solid's clean surface: kept whole.
        const auto a = icosahedron<M>();
        hmira::halfedge_mesh out;
        auto r = hmira::make_solid(out, a);
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(out.face_count(), 20u) << title;
        EXPECT_NEAR(hmira::signed_volume(out), hmira::signed_volume(a), 1e-9) << title;
    }
    if constexpr (row_measures::supported<M>) {
        EXPECT_GT(hmira::signed_volume(icosahedron<M>()), 0) << title;
    }
    if constexpr (row_surface_queries::supported<M>) {
        auto m = icosahedron<M>();
        const std::vector<hmira::vec3<double>> p{{0, 0, 0}, {5, 5, 5}};
        auto w = hmira::winding_number(m, p, {.method = hmira::winding_method::direct});
        ASSERT_TRUE(w) << title << ": " << w.error().message;
        EXPECT_NEAR(w->values[0], 1, 1e-12) << title;
        EXPECT_NEAR(w->values[1], 0, 1e-12) << title;
    }
}

// Each model's voxelization of the icosahedron must agree with face_vertex_mesh's of the same
// scalar type (float models round the generator's positions, which moves voxels on the edge).
template <class S>
std::size_t reference_voxels() {
    auto m = icosahedron<hmira::basic_face_vertex_mesh<S>>();
    auto g = hmira::voxel_grid_around(m, 8);
    auto v = hmira::voxelize(m, *g);
    return v ? v->voxels.count() : 0;
}

// The conversion and I/O rows, run on small inputs for every model that claims them (so on
// OpenMesh and CGAL too, not only compiled for them).
template <class M>
void run_conversion_claims(std::size_t column_number) {
    using T = hmira::default_traits<M>;
    const std::string title = column<M>::title;
    if constexpr (row_write::supported<M> && row_read::supported<M>) {
        const auto mesh = icosahedron<M>();
        const auto dir = std::filesystem::temp_directory_path();
        for (const char* ext : {".obj", ".off"}) {
            const auto path =
                dir / ("hmira_feature_table_" + std::to_string(::getpid()) + "_" + std::to_string(column_number) + ext);
            const bool obj = std::string(ext) == ".obj";
            auto w = obj ? hmira::io::write_obj(mesh, path) : hmira::io::write_off(mesh, path);
            ASSERT_TRUE(w) << title << ": " << w.error().message;
            M back;
            auto r = obj ? hmira::io::read_obj(back, path) : hmira::io::read_off(back, path);
            std::filesystem::remove(path);
            ASSERT_TRUE(r) << title << ": " << r.error().message;
            EXPECT_EQ(T::vertex_count(back), 12u) << title << ext;
            EXPECT_EQ(T::face_count(back), 20u) << title << ext;
            EXPECT_TRUE(valid_closed(back)) << ext;
        }
    }
    if constexpr (row_marching_cubes::supported<M>) {
        // A sphere of radius 1.8 sampled on 7^3 points: one closed surface.
        hmira::dense_grid<float> field(
            hmira::grid_geometry{.dims = {7, 7, 7}, .origin = {-3, -3, -3}, .spacing = {1, 1, 1}});
        for (std::size_t k = 0; k < 7; ++k)
            for (std::size_t j = 0; j < 7; ++j)
                for (std::size_t i = 0; i < 7; ++i) {
                    const double x = double(i) - 3, y = double(j) - 3, z = double(k) - 3;
                    field.set(i, j, k, float(std::sqrt(x * x + y * y + z * z) - 1.8));
                }
        M m;
        auto r = hmira::marching_cubes(m, field);
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_GT(r->faces.size(), 20u) << title;
        EXPECT_EQ(T::face_count(m), r->faces.size()) << title;
        EXPECT_TRUE(valid_closed(m));
    }
    if constexpr (row_voxelize::supported<M>) {
        const auto m = icosahedron<M>();
        auto g = hmira::voxel_grid_around(m, 8);
        ASSERT_TRUE(g) << title;
        auto v = hmira::voxelize(m, *g);
        ASSERT_TRUE(v) << title << ": " << v.error().message;
        EXPECT_TRUE(v->filled) << title;
        EXPECT_EQ(v->triangles, 20u) << title;
        EXPECT_EQ(v->voxels.count(), reference_voxels<typename T::scalar>()) << title;
        EXPECT_GT(v->voxels.count(), 0u) << title;
    }
    if constexpr (row_delaunay::supported<M>) {
        // Four cocircular corners and a point inside: the four triangles fanning from it.
        const points2 points{{0, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 0.8}};
        M m;
        auto r = hmira::delaunay_triangulation(m, points);
        ASSERT_TRUE(r) << title << ": " << r.error().message;
        EXPECT_EQ(T::vertex_count(m), 5u) << title;
        EXPECT_EQ(T::face_count(m), 4u) << title;
        EXPECT_EQ(r->hull.size(), 4u) << title;
        EXPECT_TRUE(hmira::validate(m).empty()) << title;
    }
}

template <class... Ms>
void run_all(model_list<Ms...>) {
    std::size_t n = 0;
    auto one = [&]<class M>() {
        ++n;
        if constexpr (std::default_initializable<M> && hmira::mesh_builder<M>) {
            run_claims<M>();
            run_editing_claims<M>();
            run_everyday_claims<M>();
            run_conversion_claims<M>(n);
        }
    };
    (one.template operator()<Ms>(), ...);
}

TEST(feature_table, the_claims_hold_when_run_on_small_meshes) { run_all(models{}); }

// Capability rows must name exactly the concepts of concepts.hpp, so the table grows with it.
TEST(feature_table, capability_rows_are_exactly_the_concepts_of_concepts_hpp) {
    const auto text = read_file(std::filesystem::path(HMIRA_SOURCE_DIR) / "include" / "hmira" / "concepts.hpp");
    std::set<std::string> declared, listed;
    const std::regex re(R"(concept\s+([A-Za-z_][A-Za-z0-9_]*)\s*=)");
    for (std::sregex_iterator it(text.begin(), text.end(), re), end; it != end; ++it)
        if ((*it)[1] != "range_of_handles") declared.insert((*it)[1]);
    [&]<class... Cs>(row_list<Cs...>) { (listed.insert(Cs::name), ...); }(capabilities{});
    EXPECT_EQ(declared, listed) << "add the new concept to `capabilities` in " << __FILE__;
}

TEST(feature_table, the_committed_table_is_the_one_the_compiler_computed) {
    const std::string generated = render();
    if (const char* out = std::getenv("HMIRA_WRITE_FEATURE_TABLE")) {
        std::ofstream(out, std::ios::binary) << generated;
        GTEST_SKIP() << "wrote " << out;
    }
    ASSERT_TRUE(std::filesystem::exists(table_path)) << table_path;
    const auto committed = parse(read_file(table_path));
    const auto now = parse(generated);
    std::vector<std::string> not_built;
    for (const auto& [section, t] : now) {
        ASSERT_TRUE(committed.count(section)) << "section '" << section << "' missing: regenerate the table";
        for (const auto& [row, cells] : t) {
            ASSERT_TRUE(committed.at(section).count(row)) << "row '" << row << "' missing: regenerate the table";
            for (const auto& [col, cell] : cells) {
                const auto& old = committed.at(section).at(row);
                ASSERT_TRUE(old.count(col)) << "column '" << col << "' missing: regenerate the table";
                EXPECT_EQ(old.at(col), cell) << section << " / " << row << " / " << col << ": the table says "
                                             << old.at(col) << ", the compiler says " << cell;
            }
        }
    }
    // The other direction: the committed table has no section or row this test does not
    // compute, and no column but the optional models'. A column this build cannot compute
    // (OpenMesh or CGAL absent) is not checked here; the full CI configuration checks it.
    const std::set<std::string> optional_columns{"OpenMesh PolyMesh", "OpenMesh TriMesh", "CGAL Surface_mesh"};
    for (const auto& [section, t] : committed) {
        EXPECT_TRUE(now.count(section)) << "the committed table has a section '" << section
                                        << "' that the test does not compute";
        if (!now.count(section)) continue;
        for (const auto& [row, cells] : t) {
            EXPECT_TRUE(now.at(section).count(row))
                << section << ": the committed table has a row '" << row << "' that the test does not know";
            if (!now.at(section).count(row)) continue;
            for (const auto& [col, cell] : cells) {
                EXPECT_TRUE(cell == "yes" || cell == "no" || col == "needs" || col == "header")
                    << section << " / " << row << " / " << col << ": '" << cell << "' is neither yes nor no";
                if (now.at(section).at(row).count(col)) continue;
                EXPECT_TRUE(optional_columns.count(col))
                    << "the committed table has a column '" << col << "' that the test does not know";
                not_built.push_back(col);
            }
        }
    }
    if (!not_built.empty())
        std::printf("note: %zu committed cells not computable in this build (optional models absent)\n",
                    not_built.size());
}

}  // namespace
