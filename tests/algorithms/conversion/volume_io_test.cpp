// Volume I/O: raw and INRIMAGE reading with clear errors, binvox and raw writing, atomically.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include <hmira/algorithms/conversion/marching_cubes.hpp>
#include <hmira/algorithms/topology/mesh_topology.hpp>
#include <hmira/grids/bit_grid.hpp>
#include <hmira/grids/dense_grid.hpp>
#include <hmira/io/points.hpp>
#include <hmira/io/volume/binvox.hpp>
#include <hmira/io/volume/inr.hpp>
#include <hmira/io/volume/raw.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>

#include "support/checks.hpp"

namespace {

namespace fs = std::filesystem;

struct temp_dir {
    fs::path path;
    temp_dir() {
        path = fs::temp_directory_path() / ("hmira-volume-io-" + std::to_string(std::random_device{}()));
        fs::create_directories(path);
    }
    ~temp_dir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
};

void write_bytes(const fs::path& p, const std::string& bytes) {
    std::ofstream out(p, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string read_bytes(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string inr_header(const std::string& fields) {
    std::string h = "#INRIMAGE-4#{\n" + fields;
    h.resize(252, '\n');
    return h + "##}\n";
}

fs::path data_dir() {
    const char* d = std::getenv("HMIRA_TEST_DATA");
    return d ? fs::path(d) : fs::path();
}

TEST(RawVolume, write_then_read_round_trips_both_byte_orders) {
    temp_dir tmp;
    hmira::dense_grid<float> g({{5, 4, 3}, {0, 0, 0}, {1, 1, 1}});
    std::mt19937 rng(3);
    for (auto& v : g.values()) v = std::uniform_real_distribution<float>(-5, 5)(rng);
    for (bool big : {false, true}) {
        const auto p = tmp.path / "v.raw";
        ASSERT_TRUE(hmira::io::write_raw(g, p, {.big_endian = big}));
        EXPECT_EQ(fs::file_size(p), g.size() * sizeof(float));
        auto back = hmira::io::read_raw<float>(p, g.geometry(), {.big_endian = big});
        ASSERT_TRUE(back);
        EXPECT_TRUE(std::equal(back->values().begin(), back->values().end(), g.values().begin()));
    }
}

TEST(RawVolume, wrong_size_nan_and_bad_geometry_are_clear_errors) {
    temp_dir tmp;
    const auto p = tmp.path / "short.raw";
    write_bytes(p, std::string(10, '\0'));
    auto r = hmira::io::read_raw<float>(p, {{2, 2, 2}, {0, 0, 0}, {1, 1, 1}});
    ASSERT_FALSE(r);
    EXPECT_EQ(r.error().code, hmira::errc::parse_error);
    EXPECT_NE(r.error().message.find("truncated"), std::string::npos);
    const float nan = std::nanf("");
    std::string bytes(8 * sizeof(float), '\0');
    std::memcpy(bytes.data() + 5 * sizeof(float), &nan, sizeof(float));
    write_bytes(p, bytes);
    auto n = hmira::io::read_raw<float>(p, {{2, 2, 2}, {0, 0, 0}, {1, 1, 1}});
    ASSERT_FALSE(n);
    EXPECT_NE(n.error().message.find("NaN"), std::string::npos);
    EXPECT_FALSE(hmira::io::read_raw<float>(p, {{2, 2, 2}, {0, 0, 0}, {1, 0, 1}}));
    EXPECT_FALSE(hmira::io::read_raw<float>(p, {{0, 2, 2}, {0, 0, 0}, {1, 1, 1}}));
    EXPECT_FALSE(hmira::io::read_raw<float>(tmp.path / "missing.raw", {{2, 2, 2}, {0, 0, 0}, {1, 1, 1}}));
}

TEST(InrVolume, reads_types_spacing_and_byte_order_of_a_written_file) {
    temp_dir tmp;
    const auto p = tmp.path / "a.inr";
    std::string data;
    for (std::uint16_t v : {1, 2, 300, 4, 5, 6}) {  // big-endian 16-bit
        data.push_back(char(v >> 8));
        data.push_back(char(v & 255));
    }
    write_bytes(
        p, inr_header(
               "XDIM=3\nYDIM=2\nZDIM=1\nVDIM=1\nTYPE=unsigned fixed\nPIXSIZE=16 bits\nCPU=sun\nVX=0.5\nVY=2\nVZ=1\n") +
               data);
    auto g = hmira::io::read_inr(p);
    ASSERT_TRUE(g) << g.error().message;
    EXPECT_EQ(g->dims(), (hmira::grid_dims{3, 2, 1}));
    EXPECT_EQ(g->spacing().x, 0.5);
    EXPECT_EQ(g->spacing().y, 2.0);
    EXPECT_EQ(g->value(2, 0, 0), 300.0f);
    EXPECT_EQ(g->value(2, 1, 0), 6.0f);
}

TEST(InrVolume, truncated_files_bad_headers_nan_and_zero_spacing_are_clear_errors) {
    temp_dir tmp;
    const auto p = tmp.path / "bad.inr";
    const std::string good =
        "XDIM=4\nYDIM=4\nZDIM=4\nVDIM=1\nTYPE=float\nPIXSIZE=32 bits\nCPU=decm\nVX=1\nVY=1\nVZ=1\n";
    auto expect_error = [&](const std::string& bytes, const char* words) {
        write_bytes(p, bytes);
        auto g = hmira::io::read_inr(p);
        ASSERT_FALSE(g) << words;
        EXPECT_NE(g.error().message.find(words), std::string::npos) << g.error().message;
    };
    expect_error(inr_header(good) + std::string(4 * 4 * 4 * 4 - 1, '\0'), "truncated");
    expect_error(inr_header(good).substr(0, 100), "terminator");
    expect_error("not an image at all", "INRIMAGE");
    expect_error(inr_header("YDIM=4\nZDIM=4\nTYPE=float\nPIXSIZE=32 bits\n") + std::string(256, '\0'), "XDIM");
    expect_error(inr_header("XDIM=4\nYDIM=4\nZDIM=4\nTYPE=complex\nPIXSIZE=32 bits\n") + std::string(256, '\0'),
                 "TYPE");
    expect_error(inr_header("XDIM=4\nYDIM=4\nZDIM=4\nVDIM=3\nTYPE=float\nPIXSIZE=32 bits\n") + std::string(768, '\0'),
                 "VDIM");
    expect_error(inr_header("XDIM=4\nYDIM=4\nZDIM=4\nTYPE=float\nPIXSIZE=32 bits\nVX=0\n") + std::string(256, '\0'),
                 "spacing");
    expect_error(inr_header("XDIM=0\nYDIM=4\nZDIM=4\nTYPE=float\nPIXSIZE=32 bits\n"), "dimension");
    std::string samples(256, '\0');
    const float nan = std::nanf("");
    std::memcpy(samples.data() + 40, &nan, 4);
    expect_error(inr_header(good) + samples, "NaN");
}

TEST(InrVolume, real_skull_volume_reads_and_gives_a_closed_surface) {
    const auto p = data_dir() / "images" / "skull_2.9.inr";
    if (data_dir().empty() || !fs::exists(p)) GTEST_SKIP() << "test data not found";
    auto g = hmira::io::read_inr(p);
    ASSERT_TRUE(g) << g.error().message;
    EXPECT_EQ(g->dims(), (hmira::grid_dims{64, 64, 64}));
    EXPECT_NEAR(g->spacing().z, 3.65079, 1e-5);
    // Truncating the real file is reported, not read as zeros.
    temp_dir tmp;
    const auto cut = tmp.path / "cut.inr";
    write_bytes(cut, read_bytes(p).substr(0, 256 + 1000));
    auto t = hmira::io::read_inr(cut);
    ASSERT_FALSE(t);
    EXPECT_NE(t.error().message.find("truncated"), std::string::npos);
    // The skull is inside above 2.9; pad with an outside layer so the surface closes.
    const auto d = g->dims();
    hmira::dense_grid<float> padded({{d[0] + 2, d[1] + 2, d[2] + 2}, g->origin(), g->spacing()}, 0.0f);
    for (std::size_t k = 0; k < d[2]; ++k)
        for (std::size_t j = 0; j < d[1]; ++j)
            for (std::size_t i = 0; i < d[0]; ++i) padded.set(i + 1, j + 1, k + 1, g->value(i, j, k));
    hmira::face_vertex_mesh m;
    ASSERT_TRUE(hmira::marching_cubes(m, padded, {.iso = 2.9, .inside = hmira::iso_inside::above}));
    EXPECT_GT(m.face_count(), 1000u);
    EXPECT_TRUE(hmira_test::is_valid(m));
    EXPECT_TRUE(hmira::mesh_topology(m).closed());
    EXPECT_GT(hmira_test::signed_volume(m), 0);
}

TEST(InrVolume, gzip_volume_reads_when_zlib_is_available) {
    const auto p = data_dir() / "images" / "liver.inr.gz";
    if (data_dir().empty() || !fs::exists(p)) GTEST_SKIP() << "test data not found";
    auto g = hmira::io::read_inr(p);
#if defined(HMIRA_HAS_ZLIB)
    ASSERT_TRUE(g) << g.error().message;
    EXPECT_EQ(g->dims(), (hmira::grid_dims{438, 353, 165}));
    float hi = 0;
    for (float v : g->values()) hi = std::max(hi, v);
    EXPECT_GT(hi, 0.0f);
    EXPECT_LE(hi, 255.0f);
    temp_dir tmp;
    const auto cut = tmp.path / "cut.inr.gz";
    write_bytes(cut, read_bytes(p).substr(0, 5000));
    EXPECT_FALSE(hmira::io::read_inr(cut));
#else
    ASSERT_FALSE(g);
    EXPECT_EQ(g.error().code, hmira::errc::unsupported);
#endif
}

TEST(Binvox, read_binvox_gives_back_what_write_binvox_wrote) {
    temp_dir tmp;
    hmira::bit_grid g({{6, 6, 6}, {1, 2, 3}, {0.5, 0.5, 0.5}});
    std::mt19937 rng(5);
    for (std::size_t k = 0; k < 6; ++k)
        for (std::size_t j = 0; j < 6; ++j)
            for (std::size_t i = 0; i < 6; ++i) g.set(i, j, k, rng() % 3 == 0);
    const auto p = tmp.path / "g.binvox";
    ASSERT_TRUE(hmira::io::write_binvox(g, p));
    auto back = hmira::io::read_binvox(p);
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(back->dims(), (hmira::grid_dims{6, 6, 6}));
    EXPECT_NEAR(back->origin().y, 2.0, 1e-12);
    EXPECT_NEAR(back->spacing().z, 0.5, 1e-12);
    for (std::size_t k = 0; k < 6; ++k)
        for (std::size_t j = 0; j < 6; ++j)
            for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(back->value(i, j, k), g.value(i, j, k));
}

TEST(Binvox, bad_binvox_files_are_named_errors_and_allocate_nothing_large) {
    const std::string head = "#binvox 1\ndim 2 2 2\ntranslate 0 0 0\nscale 1\ndata\n";
    auto expect_error = [](const std::string& bytes, const std::string& words) {
        auto g = hmira::io::parse_binvox(bytes, "v.binvox");
        ASSERT_FALSE(g) << words;
        EXPECT_EQ(g.error().code, hmira::errc::parse_error);
        EXPECT_NE(g.error().message.find(words), std::string::npos) << g.error().message;
    };
    EXPECT_TRUE(hmira::io::parse_binvox(head + std::string("\x01\x08", 2), "v.binvox"));
    expect_error(head + std::string("\x01\x07", 2), "the runs cover 7 of the 8 voxels");
    expect_error(head + std::string("\x01\x08\x00\x01", 4),
                 "v.binvox: byte offset " + std::to_string(head.size() + 2) + ": the runs cover more than");
    expect_error(head + std::string("\x02\x08", 2), "voxel value 2");
    expect_error(head + std::string("\x01\x00\x01\x08", 4), "a run of length 0");
    expect_error("#binvox 1\ndim 1025 1025 1025\ndata\n",
                 "v.binvox:2: a binvox dimension must be a whole number from 1 to 1024");
    expect_error("#binvox 1\ndim 2 2 2\nscale nan\ndata\n", "v.binvox:3: expected 'scale <s>'");
    expect_error("#binvox 1\ndim 2 2 2\ntranslate 0 inf 0\ndata\n", "v.binvox:3: expected 'translate");
    // 1024^3 voxels declared, 2 bytes of runs: refused before any grid is made.
    expect_error("#binvox 1\ndim 1024 1024 1024\ndata\n" + std::string("\x01\xff", 2),
                 "the runs cover 255 of the 1073741824 voxels");
}

TEST(PointsText, xyz_and_csv_read_with_lines_named_and_non_finite_refused) {
    auto pts = hmira::io::parse_points_text("# a comment\n1 2 3\n4,5\n\n6;7;8;9\n", "p.xyz");
    ASSERT_TRUE(pts) << pts.error().message;
    ASSERT_EQ(pts->size(), 3u);
    EXPECT_EQ((*pts)[1].z, 0.0);
    EXPECT_EQ((*pts)[2].z, 8.0);
    auto csv = hmira::io::parse_points_text("x,y,z\n1,2,3\n", "p.csv", true);
    ASSERT_TRUE(csv);
    EXPECT_EQ(csv->size(), 1u);
    auto bad = hmira::io::parse_points_text("1 2 3\n4\n", "p.xyz");
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("p.xyz:2: expected 'x y [z]'"), std::string::npos) << bad.error().message;
    auto nan = hmira::io::parse_points_text("1 2 3\n4 nan 6\n", "p.xyz");
    ASSERT_FALSE(nan);
    EXPECT_NE(nan.error().message.find("p.xyz:2: point 1 has a coordinate that is not finite"), std::string::npos)
        << nan.error().message;
    temp_dir tmp;
    const auto zero = tmp.path / "zero.xyz";
    fs::create_symlink("/dev/zero", zero);
    auto capped = hmira::io::read_points_text(zero, {.max_input_bytes = 1 << 20});
    ASSERT_FALSE(capped);
    EXPECT_NE(capped.error().message.find("input limit of 1048576 bytes"), std::string::npos) << capped.error().message;
    const auto zb = tmp.path / "zero.binvox";
    fs::create_symlink("/dev/zero", zb);
    auto capped_binvox = hmira::io::read_binvox(zb, {.max_input_bytes = 1 << 20});
    ASSERT_FALSE(capped_binvox);
    EXPECT_NE(capped_binvox.error().message.find("input limit of 1048576 bytes"), std::string::npos)
        << capped_binvox.error().message;
}

// ---- hostile volumes ---------------------------------------------------------------------------
#if defined(HMIRA_HAS_ZLIB)
/// One gzip member holding `bytes` (deflate level 9).
std::string gzip(const std::string& bytes) {
    z_stream z{};
    EXPECT_EQ(deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY), Z_OK);
    std::string out(deflateBound(&z, static_cast<uLong>(bytes.size())) + 64, '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
    z.avail_in = static_cast<uInt>(bytes.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    EXPECT_EQ(deflate(&z, Z_FINISH), Z_STREAM_END);
    out.resize(z.total_out);
    deflateEnd(&z);
    return out;
}

/// A gzip bomb: a 16^3 float volume's header (16 KiB of samples declared) followed by
/// `mib` MiB of zeros, as concatenated gzip members (gunzip reads them as one stream), so
/// that a 1 GiB bomb takes a millisecond to build.
std::string inr_gzip_bomb(std::size_t mib) {
    std::string bomb = gzip(inr_header("XDIM=16\nYDIM=16\nZDIM=16\nTYPE=float\nPIXSIZE=32 bits\n"));
    const std::string zeros = gzip(std::string(1 << 20, '\0'));
    for (std::size_t i = 0; i < mib; ++i) bomb += zeros;
    return bomb;
}

TEST(InrVolume, a_gzip_bomb_is_refused_after_inflating_no_more_than_the_header_declares) {
    temp_dir tmp;
    const auto p = tmp.path / "bomb.inr.gz";
    const auto bomb = inr_gzip_bomb(1024);  // 1 GiB inflated, about 1 MB on disk
    EXPECT_LT(bomb.size(), 2u << 20);
    write_bytes(p, bomb);
    auto g = hmira::io::read_inr(p);
    ASSERT_FALSE(g);
    EXPECT_EQ(g.error().code, hmira::errc::parse_error);
    EXPECT_NE(g.error().message.find(p.string() + ": "), std::string::npos) << g.error().message;
    EXPECT_NE(g.error().message.find("goes on past the 16384 bytes of samples the header declares"), std::string::npos)
        << g.error().message;
}

TEST(InrVolume, gzip_data_shorter_or_longer_than_the_header_declares_is_an_error) {
    temp_dir tmp;
    const auto p = tmp.path / "v.inr.gz";
    const std::string head = inr_header("XDIM=4\nYDIM=4\nZDIM=4\nTYPE=unsigned fixed\nPIXSIZE=8 bits\n");
    write_bytes(p, gzip(head + std::string(64, '\x07')));
    auto ok = hmira::io::read_inr(p);
    ASSERT_TRUE(ok) << ok.error().message;
    EXPECT_EQ(ok->value(3, 3, 3), 7.0f);
    write_bytes(p, gzip(head + std::string(63, '\x07')));
    auto short_one = hmira::io::read_inr(p);
    ASSERT_FALSE(short_one);
    EXPECT_NE(short_one.error().message.find("truncated: the header promises 64 bytes of samples, the file holds 63"),
              std::string::npos)
        << short_one.error().message;
    write_bytes(p, gzip(head + std::string(65, '\x07')));
    auto long_one = hmira::io::read_inr(p);
    ASSERT_FALSE(long_one);
    EXPECT_NE(long_one.error().message.find("goes on past the 64 bytes of samples"), std::string::npos)
        << long_one.error().message;
    // A header split over two gzip members still reads.
    write_bytes(p, gzip(head.substr(0, 100)) + gzip(head.substr(100) + std::string(64, '\x07')));
    EXPECT_TRUE(hmira::io::read_inr(p));
}
#endif

TEST(InrVolume, plain_data_past_the_declared_samples_is_an_error) {
    temp_dir tmp;
    const auto p = tmp.path / "long.inr";
    write_bytes(p,
                inr_header("XDIM=2\nYDIM=2\nZDIM=2\nTYPE=unsigned fixed\nPIXSIZE=8 bits\n") + std::string(8 + 5, '\0'));
    auto g = hmira::io::read_inr(p);
    ASSERT_FALSE(g);
    EXPECT_EQ(g.error().code, hmira::errc::parse_error);
    EXPECT_NE(g.error().message.find("5 bytes after the 8 bytes of samples the header declares"), std::string::npos)
        << g.error().message;
}

TEST(InrVolume, header_values_out_of_range_are_parse_errors_naming_the_key) {
    temp_dir tmp;
    const auto p = tmp.path / "h.inr";
    const std::string rest = "TYPE=float\nPIXSIZE=32 bits\n";
    struct bad_header {
        std::string fields, key;
    };
    for (const auto& c :
         std::vector<bad_header>{{"XDIM=0\nYDIM=2\nZDIM=2\n" + rest, "XDIM=0"},
                                 {"XDIM=2.5\nYDIM=2\nZDIM=2\n" + rest, "XDIM=2.5"},
                                 {"XDIM=1e300\nYDIM=2\nZDIM=2\n" + rest, "XDIM=1e300"},
                                 {"XDIM=2\nYDIM=2\nZDIM=2\nVX=nan\n" + rest, "VX=nan"},
                                 {"XDIM=2\nYDIM=2\nZDIM=2\nVX=0\n" + rest, "VX=0"},
                                 {"XDIM=2\nYDIM=2\nZDIM=2\nVY=-1\n" + rest, "VY=-1"},
                                 {"XDIM=2\nYDIM=2\nZDIM=2\nTX=inf\n" + rest, "TX=inf"},
                                 {"XDIM=2\nYDIM=2\nZDIM=2\nTYPE=float\nPIXSIZE=1e20 bits\n", "PIXSIZE=1e20"},
                                 {"XDIM=2\nYDIM=2\nZDIM=2\nTYPE=float\nPIXSIZE=-8 bits\n", "PIXSIZE=-8"},
                                 {"XDIM=1000000\nYDIM=1000000\nZDIM=1000000\n" + rest, "too large"}}) {
        SCOPED_TRACE(c.fields);
        write_bytes(p, inr_header(c.fields) + std::string(32, '\0'));
        auto g = hmira::io::read_inr(p);
        ASSERT_FALSE(g);
        EXPECT_EQ(g.error().code, hmira::errc::parse_error)
            << g.error().message;  // a problem of the file, not of the call
        EXPECT_NE(g.error().message.find(p.string()), std::string::npos) << g.error().message;
        EXPECT_NE(g.error().message.find(c.key), std::string::npos) << g.error().message;
        EXPECT_EQ(g.error().message.find('\n'), std::string::npos) << g.error().message;
    }
}

TEST(VolumeInput, endless_devices_stop_at_the_input_limit) {
    temp_dir tmp;
    const auto inr = tmp.path / "zero.inr", raw = tmp.path / "zero.raw";
    fs::create_symlink("/dev/zero", inr);
    fs::create_symlink("/dev/zero", raw);
    auto g = hmira::io::read_inr(inr, {.max_input_bytes = 1 << 20});
    ASSERT_FALSE(g);
    EXPECT_EQ(g.error().code, hmira::errc::unsupported);
    EXPECT_NE(
        g.error().message.find(inr.string() + ": not a regular file, and longer than the input limit of 1048576 bytes"),
        std::string::npos)
        << g.error().message;
    auto r = hmira::io::read_raw<float>(raw, {{4, 4, 4}, {0, 0, 0}, {1, 1, 1}}, {.max_input_bytes = 1 << 20});
    ASSERT_FALSE(r);
    EXPECT_NE(r.error().message.find("input limit of 1048576 bytes"), std::string::npos) << r.error().message;
}

// An independent reader of what write_binvox produced, following the format description.
std::vector<std::uint8_t> decode_binvox(const std::string& bytes, std::size_t& d) {
    const auto data = bytes.find("data\n");
    std::istringstream head(bytes.substr(0, data));
    std::string word;
    head >> word >> word >> word >> d;
    std::vector<std::uint8_t> out;
    for (std::size_t q = data + 5; q + 1 < bytes.size(); q += 2)
        out.insert(out.end(), std::uint8_t(bytes[q + 1]), std::uint8_t(bytes[q]));
    return out;
}

TEST(Binvox, written_occupancy_decodes_back_with_padding_to_a_cube) {
    temp_dir tmp;
    hmira::bit_grid g({{5, 3, 4}, {1, 2, 3}, {0.5, 0.5, 0.5}});
    std::mt19937 rng(11);
    for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t j = 0; j < 3; ++j)
            for (std::size_t i = 0; i < 5; ++i) g.set(i, j, k, rng() % 2);
    const auto p = tmp.path / "g.binvox";
    ASSERT_TRUE(hmira::io::write_binvox(g, p));
    const auto bytes = read_bytes(p);
    EXPECT_EQ(bytes.rfind("#binvox 1\ndim 5 5 5\n", 0), 0u);
    EXPECT_NE(bytes.find("translate 0.75 1.75 2.75"), std::string::npos);
    EXPECT_NE(bytes.find("scale 2.5"), std::string::npos);
    std::size_t d = 0;
    const auto vox = decode_binvox(bytes, d);
    ASSERT_EQ(vox.size(), d * d * d);
    for (std::size_t i = 0; i < d; ++i)
        for (std::size_t k = 0; k < d; ++k)
            for (std::size_t j = 0; j < d; ++j) {
                const int want = (i < 5 && j < 3 && k < 4) ? g.value(i, j, k) : 0;
                EXPECT_EQ(vox[i * d * d + k * d + j], want);
            }
}

TEST(VolumeWriters, failed_writes_leave_existing_files_and_refuse_bad_grids) {
    temp_dir tmp;
    const auto p = tmp.path / "keep.raw";
    write_bytes(p, "old");
    hmira::dense_grid<float> empty({{0, 1, 1}, {0, 0, 0}, {1, 1, 1}});
    EXPECT_FALSE(hmira::io::write_raw(empty, p));
    EXPECT_EQ(read_bytes(p), "old");
    hmira::bit_grid aniso({{2, 2, 2}, {0, 0, 0}, {1, 2, 1}});
    EXPECT_FALSE(hmira::io::write_binvox(aniso, tmp.path / "a.binvox"));
    EXPECT_FALSE(fs::exists(tmp.path / "a.binvox"));
    hmira::dense_grid<float> ok({{2, 2, 2}, {0, 0, 0}, {1, 1, 1}});
    EXPECT_FALSE(hmira::io::write_raw(ok, tmp.path / "no-such-folder" / "x.raw"));
    EXPECT_EQ(std::distance(fs::directory_iterator(tmp.path), fs::directory_iterator()), 1);
}

}  // namespace
