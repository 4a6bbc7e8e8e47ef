// VTK PolyData (.vtp, legacy .vtk) and 3MF: what the writers write, the readers read back as the
// same mesh on every model (positions bit for bit, faces compared through canonical forms the
// test computes; 3MF triangulates); hand-written files check strips, unstructured grids,
// big-endian and compressed arrays, 3MF transforms and components; hostile bytes give
// bounded one-line errors naming what and where.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <hmira/algorithms/generators/platonic_solids.hpp>
#include <hmira/io/mesh_io.hpp>

#include "io/io_support.hpp"
#include "support/checks.hpp"
#include "support/models.hpp"
#include "support/shapes.hpp"

namespace {

using namespace hmira;
using hmira_test::scratch_dir;

// The signed volume by the divergence theorem, from the soup's triangles (fanned).
double volume(const io::polygon_soup& s) {
    double sum = 0;
    for (std::size_t f = 0; f < s.face_count(); ++f)
        for (auto k = s.face_offsets[f] + 1; k + 1 < s.face_offsets[f + 1]; ++k) {
            const auto& a = s.points[s.indices[s.face_offsets[f]]];
            const auto& b = s.points[s.indices[k]];
            const auto& c = s.points[s.indices[k + 1]];
            sum += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                   a[2] * (b[0] * c[1] - b[1] * c[0]);
        }
    return sum / 6;
}

hmira_test::face_list jittered_torus() {
    auto g = hmira_test::torus(12, 8);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> d(-1e-3, 1e-3);
    for (auto& p : g.points) p += vec3<double>{d(rng), d(rng), d(rng)};
    return g;
}

template <class M>
class vtk_3mf_round_trip : public ::testing::Test {};
TYPED_TEST_SUITE(vtk_3mf_round_trip, hmira_test::all_models);

TYPED_TEST(vtk_3mf_round_trip, every_encoding_gives_back_the_same_mesh) {
    TypeParam torus, dodeca;
    ASSERT_TRUE(hmira_test::add_face_list(torus, jittered_torus()));
    ASSERT_TRUE(generate_dodecahedron(dodeca, {.scale = 1.7}));
    for (const TypeParam* m : {&torus, &dodeca}) {
        const auto original = hmira_test::geometric_faces(*m, hmira_test::exact);
        const auto triangulated = hmira_test::geometric_faces(*m, hmira_test::exact, true);
        for (const char* ext : {".vtp", ".vtk", ".3mf"}) {
            SCOPED_TRACE(ext);
            scratch_dir dir;
            const auto path = dir / (std::string("m") + ext);
            auto w = io::write_mesh(*m, path);
            ASSERT_TRUE(w) << w.error().message;
            TypeParam back;
            auto r = io::read_mesh(back, path);
            ASSERT_TRUE(r) << r.error().message;
            EXPECT_TRUE(hmira_test::is_valid(back));
            EXPECT_EQ(hmira_test::positions(back), hmira_test::positions(*m));
            const bool triangles = std::string(ext) == ".3mf";
            EXPECT_EQ(hmira_test::geometric_faces(back, hmira_test::exact, false), triangles ? triangulated : original);
            EXPECT_EQ(dir.files(), std::vector<std::string>{path.filename().string()});
        }
    }
}

TEST(vtk, the_four_encodings_parse_to_the_same_soup) {
    halfedge_mesh cube;
    ASSERT_TRUE(generate_cube(cube));
    std::vector<io::polygon_soup> soups;
    for (auto e : {io::vtk_encoding::xml_appended, io::vtk_encoding::xml_base64, io::vtk_encoding::legacy_binary,
                   io::vtk_encoding::legacy_ascii}) {
        auto bytes = io::format_vtk(cube, e);
        ASSERT_TRUE(bytes);
        auto s = io::parse_vtk(*bytes, "cube");
        ASSERT_TRUE(s) << s.error().message;
        soups.push_back(std::move(*s));
    }
    for (const auto& s : soups) {
        EXPECT_EQ(s.points, soups[0].points);
        EXPECT_EQ(s.indices, soups[0].indices);
        EXPECT_EQ(s.face_offsets, soups[0].face_offsets);
        EXPECT_EQ(s.face_count(), 6u);
    }
    EXPECT_NEAR(std::abs(volume(soups[0])), 8.0, 1e-12);  // generate_cube is [-1, 1]^3
}

// One quad strip of 4 points: triangles (0 1 2) and (2 1 3), both wound like the first.
TEST(vtk, legacy_strips_and_unstructured_grid_cells) {
    const std::string head = "# vtk DataFile Version 3.0\nx\nASCII\nDATASET ";
    const std::string pts = "POINTS 4 float\n0 0 0 1 0 0 0 1 0 1 1 0\n";
    auto strips = io::parse_vtk(head + "POLYDATA\n" + pts + "TRIANGLE_STRIPS 1 5\n4 0 1 2 3\n", "s.vtk");
    ASSERT_TRUE(strips) << strips.error().message;
    EXPECT_EQ(strips->indices, (std::vector<std::uint32_t>{0, 1, 2, 2, 1, 3}));
    auto grid = io::parse_vtk(
        head + "UNSTRUCTURED_GRID\n" + pts + "CELLS 3 11\n3 0 1 2\n2 0 3\n3 1 3 2\nCELL_TYPES 3\n5 3 5\nPOINT_DATA 4\n",
        "g.vtk");
    ASSERT_TRUE(grid) << grid.error().message;
    EXPECT_EQ(grid->face_count(), 2u);  // the line cell (type 3) is skipped
    EXPECT_EQ(grid->indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
    auto v5 = io::parse_vtk("# vtk DataFile Version 5.1\nx\nASCII\nDATASET POLYDATA\n" + pts +
                                "METADATA\nINFORMATION 0\n\nPOLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\n"
                                "CONNECTIVITY vtktypeint64\n0 1 2\n",
                            "v5.vtk");
    ASSERT_TRUE(v5) << v5.error().message;
    EXPECT_EQ(v5->indices, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(vtk, xml_ascii_big_endian_and_compressed_arrays) {
    const std::string piece =
        "<Piece NumberOfPoints=\"3\" NumberOfPolys=\"1\"><Points><DataArray type=\"Float64\" "
        "NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray></Points><Polys>"
        "<DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>"
        "<DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3</DataArray></Polys></Piece>";
    auto ascii = io::parse_vtk(
        "<?xml version=\"1.0\"?><VTKFile type=\"PolyData\"><PolyData>" + piece + "</PolyData></VTKFile>", "a.vtp");
    ASSERT_TRUE(ascii) << ascii.error().message;
    EXPECT_EQ(ascii->points[1], (std::array<double, 3>{1, 0, 0}));
    // Big-endian, UInt32 header, inline base64: "AAAADA==" is the header 12, then Int32 0 1 2.
    auto be = io::parse_vtk(
        "<VTKFile type=\"PolyData\" byte_order=\"BigEndian\"><PolyData><Piece NumberOfPoints=\"3\" "
        "NumberOfPolys=\"1\"><Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" "
        "format=\"ascii\">0 0 0 1 0 0 0 1 0</DataArray></Points><Polys><DataArray type=\"Int32\" "
        "Name=\"connectivity\" format=\"binary\">AAAADA==AAAAAAAAAAEAAAAC</DataArray><DataArray type=\"Int32\" "
        "Name=\"offsets\" format=\"ascii\">3</DataArray></Polys></Piece></PolyData></VTKFile>",
        "be.vtp");
    ASSERT_TRUE(be) << be.error().message;
    EXPECT_EQ(be->indices, (std::vector<std::uint32_t>{0, 1, 2}));
    // zlib-compressed: one block of the Int32s 0 1 2 (header 1, 12, 12, compressed size).
    if constexpr (io::detail::has_zlib) {
        const std::string raw("\0\0\0\0\1\0\0\0\2\0\0\0", 12);
        const std::string packed = io::detail::deflate_bytes(raw, false);
        std::string block;
        for (std::uint32_t v : {1u, 12u, 12u, static_cast<std::uint32_t>(packed.size())})
            block.append(reinterpret_cast<const char*>(&v), 4);
        const std::string doc =
            "<VTKFile type=\"PolyData\" compressor=\"vtkZLibDataCompressor\"><PolyData><Piece NumberOfPoints=\"3\" "
            "NumberOfPolys=\"1\"><Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">"
            "0 0 0 1 0 0 0 1 0</DataArray></Points><Polys><DataArray type=\"Int32\" Name=\"connectivity\" "
            "format=\"appended\" offset=\"0\"/><DataArray type=\"Int32\" Name=\"offsets\" format=\"ascii\">3"
            "</DataArray></Polys></Piece></PolyData><AppendedData encoding=\"raw\">_" +
            block + packed + "</AppendedData></VTKFile>";
        auto z = io::parse_vtk(doc, "z.vtp");
        ASSERT_TRUE(z) << z.error().message;
        EXPECT_EQ(z->indices, (std::vector<std::uint32_t>{0, 1, 2}));
        // The same block declaring a 2^40-byte block size: refused before inflating.
        std::string bomb;
        for (std::uint32_t v : {1u, 0x7fffffffu, 0x7fffffffu, static_cast<std::uint32_t>(packed.size())})
            bomb.append(reinterpret_cast<const char*>(&v), 4);
        auto refused = io::parse_vtk(doc.substr(0, doc.find('_') + 1) + bomb + packed + "</AppendedData></VTKFile>",
                                     "bomb.vtp", {.max_input_bytes = 1 << 20});
        ASSERT_FALSE(refused);
        EXPECT_NE(refused.error().message.find("input limit"), std::string::npos) << refused.error().message;
    }
}

TEST(vtk, hostile_inputs_give_bounded_errors_naming_what_and_where) {
    halfedge_mesh cube;
    ASSERT_TRUE(generate_cube(cube));
    const auto legacy = *io::format_vtk(cube, io::vtk_encoding::legacy_binary);
    const auto vtp = *io::format_vtk(cube, io::vtk_encoding::xml_appended);
    struct bad_case {
        std::string bytes, expect;
    };
    const std::string head = "# vtk DataFile Version 3.0\nx\nBINARY\nDATASET POLYDATA\n";
    std::string nan_points =
        "# vtk DataFile Version 3.0\nx\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 nan 0 0 0 1 0\n";
    std::string offset = vtp;
    offset.replace(offset.find("offset=\"0\""), 10, "offset=\"999999\"");
    std::string xml_count = vtp;
    xml_count.replace(xml_count.find("NumberOfPoints=\"8\""), 18, "NumberOfPoints=\"99999999\"");
    const std::vector<bad_case> cases = {
        {legacy.substr(0, legacy.size() - 50), "POLYGONS"},
        {head + "POINTS 4000000000 float\n", "more than the"},
        {head + "POINTS 0 float\nPOLYGONS 1000000000 1000000000\n", "more than the"},
        {nan_points, "not finite"},
        {vtp.substr(0, vtp.size() - 40), "byte"},
        {vtp.substr(0, 300), "ends"},
        {offset, "offset 999999"},
        {xml_count, "Points"},
        {"<VTKFile type=\"PolyData\"><!DOCTYPE x [<!ENTITY a \"b\">]></VTKFile>", "DOCTYPE"},
        {"<VTKFile type=\"ImageData\"/>", "PolyData"},
        {"plain text", "neither"},
    };
    for (const auto& c : cases) {
        auto s = io::parse_vtk(c.bytes, "h.vtk");
        ASSERT_FALSE(s) << c.expect;
        EXPECT_NE(s.error().message.find(c.expect), std::string::npos) << s.error().message;
        EXPECT_EQ(s.error().message.find('\n'), std::string::npos) << s.error().message;
        EXPECT_TRUE(s.error().message.starts_with("h.vtk: ")) << s.error().message;
    }
}

// A 3MF package by hand: `model` as its model part (stored), rels naming it.
std::string package(const std::string& model, const std::string& part = "3D/3dmodel.model") {
    const std::string rels =
        "<Relationships><Relationship Target=\"/" + part +
        "\" Id=\"r\" Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>";
    return io::detail::zip_archive({{"_rels/.rels", rels}, {part, model}}, false);
}

const std::string unit_triangle_object =
    "<object id=\"1\"><mesh><vertices><vertex x=\"0\" y=\"0\" z=\"0\"/><vertex x=\"1\" y=\"0\" z=\"0\"/>"
    "<vertex x=\"0\" y=\"1\" z=\"0\"/></vertices><triangles><triangle v1=\"0\" v2=\"1\" v3=\"2\"/></triangles>"
    "</mesh></object>";

TEST(threemf, build_items_and_components_are_placed_by_their_transforms) {
    const std::string model =
        "<?xml version=\"1.0\"?><model xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">"
        "<resources>" +
        unit_triangle_object +
        "<object id=\"2\"><components><component objectid=\"1\" transform=\"2 0 0 0 2 0 0 0 2 0 0 5\"/>"
        "</components></object></resources><build><item objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 10 0 0\"/>"
        "<item objectid=\"2\" transform=\"0 1 0 -1 0 0 0 0 1 0 0 0\"/></build></model>";
    auto s = io::parse_3mf(package(model, "3D/other.model"), "t.3mf");
    ASSERT_TRUE(s) << s.error().message;
    ASSERT_EQ(s->points.size(), 6u);
    EXPECT_EQ(s->points[1], (std::array<double, 3>{11, 0, 0}));
    // Component scales by 2 and lifts by 5, then the item turns x into y: (1,0,0) -> (0,2,5).
    EXPECT_EQ(s->points[4], (std::array<double, 3>{0, 2, 5}));
    EXPECT_EQ(s->points[5], (std::array<double, 3>{-2, 0, 5}));
    EXPECT_EQ(s->indices, (std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5}));
}

TEST(threemf, written_packages_are_valid_zips_with_the_three_parts) {
    halfedge_mesh cube;
    ASSERT_TRUE(generate_cube(cube));
    auto bytes = io::format_3mf(cube);
    ASSERT_TRUE(bytes);
    auto entries = io::detail::zip_directory(*bytes, "c.3mf");
    ASSERT_TRUE(entries) << entries.error().message;
    std::vector<std::string> names;
    for (const auto& e : *entries) {
        names.push_back(e.name);
        EXPECT_EQ(e.method, io::detail::has_zlib ? 8 : 0) << e.name;
    }
    EXPECT_EQ(names, (std::vector<std::string>{"[Content_Types].xml", "_rels/.rels", "3D/3dmodel.model"}));
    auto s = io::parse_3mf(*bytes, "c.3mf");
    ASSERT_TRUE(s) << s.error().message;
    EXPECT_EQ(s->face_count(), 12u);
    EXPECT_DOUBLE_EQ(std::abs(volume(*s)), 8.0);
}

TEST(threemf, hostile_packages_give_bounded_errors_naming_what_and_where) {
    halfedge_mesh cube;
    ASSERT_TRUE(generate_cube(cube));
    const auto good = *io::format_3mf(cube);
    const std::string head = "<model><resources>";
    std::string bad_crc =
        package(head + unit_triangle_object + "</resources><build><item objectid=\"1\"/></build></model>");
    bad_crc[bad_crc.find("<vertex") + 3] ^= 1;  // a stored entry's byte, so only the CRC notices
    std::string huge =
        package(head + unit_triangle_object + "</resources><build><item objectid=\"1\"/></build></model>");
    {  // the model's declared size (central directory) made 3 GB
        const auto dir = huge.rfind(std::string("PK\1\2", 4));
        huge[dir + 24] = '\0', huge[dir + 25] = '\0', huge[dir + 26] = '\0', huge[dir + 27] = '\xb0';
    }
    std::string many_items;
    for (int i = 0; i < 50; ++i) many_items += "<item objectid=\"1\"/>";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {good.substr(0, good.size() - 10), "end of central directory"},
        {good.substr(0, good.size() / 2), "central directory"},
        {bad_crc, "CRC"},
        {huge, "over the input limit"},
        {package(head + "<object id=\"1\"><mesh><vertices><vertex x=\"0\" y=\"nan\" z=\"0\"/></vertices></mesh>"
                        "</object></resources></model>"),
         "object 1: vertex 0"},
        {package(head + "<object id=\"1\"><mesh><vertices><vertex x=\"0\" y=\"0\" z=\"0\"/></vertices><triangles>"
                        "<triangle v1=\"0\" v2=\"0\" v3=\"7\"/></triangles></mesh></object></resources></model>"),
         "triangle 0 names a vertex out of range"},
        {package(head + "<object id=\"1\"><components><component objectid=\"1\"/></components></object></resources>"
                        "<build><item objectid=\"1\"/></build></model>"),
         "contains itself"},
        {package(head + "</resources><build><item objectid=\"9\"/></build></model>"), "object 9"},
        {package(head + unit_triangle_object + "</resources><build>" + many_items + "</build></model>"),
         "over the input limit"},
        {"PK\3\4 not really a zip at all, just text long enough", "end of central directory"},
    };
    for (const auto& [bytes, expect] : cases) {
        auto s = io::parse_3mf(bytes, "h.3mf", {.max_input_bytes = 24 * 100});
        ASSERT_FALSE(s) << expect;
        EXPECT_NE(s.error().message.find(expect), std::string::npos) << s.error().message;
        EXPECT_EQ(s.error().message.find('\n'), std::string::npos) << s.error().message;
        EXPECT_TRUE(s.error().message.starts_with("h.3mf")) << s.error().message;
    }
}

TEST(threemf, writers_refuse_non_finite_coordinates_and_leave_no_file) {
    face_vertex_mesh m;
    ASSERT_TRUE(generate_tetrahedron(m));
    default_traits<face_vertex_mesh>::set_position(m, vertex_handle(2), {0, std::nan(""), 0});
    scratch_dir dir;
    for (const char* name : {"t.3mf", "t.vtp", "t.vtk"}) {
        auto w = io::write_mesh(m, dir / name);
        ASSERT_FALSE(w) << name;
        EXPECT_NE(w.error().message.find("vertex 2"), std::string::npos) << w.error().message;
    }
    EXPECT_TRUE(dir.files().empty());
}

}  // namespace
