// tests/io/io_support.hpp
// Helpers for the I/O suites: a scratch folder per test, files written byte for byte, and
// canonical forms of a mesh computed here (not by the code under test) for comparisons.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <hmira/algorithms/triangulation/triangulate_faces.hpp>
#include <hmira/concepts.hpp>

namespace hmira_test {

/// A fresh empty folder, removed when the object goes away.
class scratch_dir {
public:
    scratch_dir() {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        std::string name = std::string("hmira-io-") + std::to_string(::getpid()) + "-" +
                           (info ? info->test_suite_name() : "x") + "-" + (info ? info->name() : "y");
        std::replace(name.begin(), name.end(), '/', '_');
        path_ = std::filesystem::temp_directory_path() / name;
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~scratch_dir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    std::filesystem::path operator/(const std::string& f) const { return path_ / f; }
    const std::filesystem::path& path() const { return path_; }
    /// Files in the folder (to check that nothing, not even a temporary, was left behind).
    std::vector<std::string> files() const {
        std::vector<std::string> out;
        for (const auto& e : std::filesystem::directory_iterator(path_)) out.push_back(e.path().filename().string());
        std::sort(out.begin(), out.end());
        return out;
    }

private:
    std::filesystem::path path_;
};

inline void write_bytes(const std::filesystem::path& p, const std::string& bytes) {
    std::ofstream o(p, std::ios::binary);
    o.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

inline std::string read_bytes(const std::filesystem::path& p) {
    std::ifstream i(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(i), {});
}

using point3 = std::array<double, 3>;

/// Faces as loops of positions, each rotated to start at its smallest position: compares two
/// meshes independently of vertex numbering and face order. `round` maps coordinates first
/// (for example to float for STL). `triangulate`: polygons become the triangles the STL writer
/// is specified to write (face_triangles), so an STL file read back compares equal.
template <class M, class T = hmira::default_traits<M>, class Round>
std::multiset<std::vector<point3>> geometric_faces(const M& mesh, Round round, bool triangulate = false) {
    std::multiset<std::vector<point3>> out;
    for (auto f : T::faces(mesh)) {
        std::vector<point3> loop;
        auto at = [&](typename T::vertex_handle v) {
            const auto p = T::position(mesh, v);
            return point3{round(double(p[0])), round(double(p[1])), round(double(p[2]))};
        };
        for (auto v : T::face_vertices(mesh, f)) loop.push_back(at(v));
        auto canon = [](std::vector<point3> l) {
            std::rotate(l.begin(), std::min_element(l.begin(), l.end()), l.end());
            return l;
        };
        if (triangulate && loop.size() > 3) {
            if constexpr (hmira::face_triangulable_mesh<M, T>) {
                auto tris = hmira::face_triangles<M, T>(mesh, f);
                EXPECT_TRUE(tris) << tris.error().message;
                if (tris)
                    for (const auto& t : *tris) out.insert(canon({at(t[0]), at(t[1]), at(t[2])}));
            } else {
                for (std::size_t i = 1; i + 1 < loop.size(); ++i) out.insert(canon({loop[0], loop[i], loop[i + 1]}));
            }
        } else {
            out.insert(canon(loop));
        }
    }
    return out;
}

inline double exact(double x) { return x; }
inline double to_float(double x) { return double(float(x)); }

/// Positions in vertex-index order.
template <class M, class T = hmira::default_traits<M>>
std::vector<point3> positions(const M& mesh) {
    std::vector<point3> out;
    for (auto v : T::vertices(mesh)) {
        const auto p = T::position(mesh, v);
        out.push_back({double(p[0]), double(p[1]), double(p[2])});
    }
    return out;
}

}  // namespace hmira_test
