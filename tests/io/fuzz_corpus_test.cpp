// Replays the committed fuzz corpus (fuzz/corpus/<format>/*) through the same property the
// fuzz targets check, under the normal build: no crash, no sanitizer finding, and every file
// that parses survives a write-and-read-again round trip.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "../../fuzz/fuzz_io.hpp"
#if defined(HMIRA_FUZZ_VOLUMES)
#include "../../fuzz/fuzz_volume.hpp"
#endif

namespace {

/// Runs `one` on every file of fuzz/corpus/<folder>; each must give "".
template <class One>
void replay_with(const char* folder, One one) {
    const std::filesystem::path dir = std::filesystem::path(HMIRA_FUZZ_CORPUS) / folder;
    ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
    std::size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), {});
        EXPECT_EQ(one(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), "") << e.path();
        ++files;
    }
    EXPECT_GE(files, 5u) << "the corpus for " << folder << " is nearly empty";
}

void replay(const char* folder, hmira::io::file_format format) {
    const std::filesystem::path dir = std::filesystem::path(HMIRA_FUZZ_CORPUS) / folder;
    ASSERT_TRUE(std::filesystem::is_directory(dir)) << dir;
    std::size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        if (!e.is_regular_file()) continue;
        std::ifstream in(e.path(), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), {});
        EXPECT_EQ(hmira_fuzz::one_input(format, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()), "")
            << e.path();
        ++files;
    }
    EXPECT_GE(files, 5u) << "the corpus for " << folder << " is nearly empty";
}

TEST(fuzz_corpus, every_obj_input_is_handled) { replay("obj", hmira::io::file_format::obj); }
TEST(fuzz_corpus, every_off_input_is_handled) { replay("off", hmira::io::file_format::off); }
TEST(fuzz_corpus, every_ply_input_is_handled) { replay("ply", hmira::io::file_format::ply); }
TEST(fuzz_corpus, every_stl_input_is_handled) { replay("stl", hmira::io::file_format::stl); }
TEST(fuzz_corpus, every_gltf_input_is_handled) { replay("gltf", hmira::io::file_format::glb); }
TEST(fuzz_corpus, every_vtk_input_is_handled) { replay("vtk", hmira::io::file_format::vtp); }
TEST(fuzz_corpus, every_3mf_input_is_handled) { replay("3mf", hmira::io::file_format::threemf); }

#if defined(HMIRA_FUZZ_VOLUMES)
TEST(fuzz_corpus, every_inr_input_is_handled) {
    replay_with("inr", [](const std::uint8_t* d, std::size_t n) { return hmira_fuzz::one_inr(d, n, false); });
}
TEST(fuzz_corpus, every_inr_gz_input_is_handled) {
    replay_with("inr_gz", [](const std::uint8_t* d, std::size_t n) { return hmira_fuzz::one_inr(d, n, true); });
}
TEST(fuzz_corpus, every_binvox_input_is_handled) { replay_with("binvox", hmira_fuzz::one_binvox); }
TEST(fuzz_corpus, every_points_input_is_handled) { replay_with("points", hmira_fuzz::one_points); }
#endif

}  // namespace
