// All-pairs check of mesh_boolean on the test data, outside CI: every closed, self-intersection-
// free mesh of <dir> (default $HMIRA_TEST_DATA/meshes), polygons triangulated, against a rotated and
// translated copy of itself and of the next such mesh (scaled to its size), under union,
// intersection and difference.
// A pair passes when every operation succeeds, every result is closed, self_intersections() of each
// result is empty or equals the report's rounding_intersections, and the volume identities
// vol(A u B) + vol(A n B) = vol(A) + vol(B), vol(A - B) = vol(A) - vol(A n B) hold within 1e-9
// relative. Prints one line per pair and the pass count.
//   usage: boolean_all_pairs [dir] [max_faces]
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <hmira/algorithms/boolean/mesh_boolean.hpp>
#include <hmira/algorithms/validation/self_intersections.hpp>
#include <hmira/io/mesh_io.hpp>
#include <hmira/meshes/face_vertex_mesh.hpp>
#include <hmira/meshes/halfedge_mesh.hpp>

namespace {

using namespace hmira;
using mesh = hmira::face_vertex_mesh;
using tr = default_traits<mesh>;
using box3 = std::array<std::array<double, 3>, 2>;

box3 bounds(const mesh& m) {
    box3 b{{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}}};
    for (auto v : tr::vertices(m)) {
        const auto p = tr::position(m, v);
        for (std::size_t k = 0; k < 3; ++k)
            b[0][k] = std::min(b[0][k], double(p[k])), b[1][k] = std::max(b[1][k], double(p[k]));
    }
    return b;
}

double diagonal(const box3& b) { return std::hypot(b[1][0] - b[0][0], b[1][1] - b[0][1], b[1][2] - b[0][2]); }

/// m rotated about its box's centre, scaled to the box `to`, placed at its centre moved by
/// `shift` times its extent (the same transformation as tests/algorithms/boolean/real_meshes_test).
mesh moved(const mesh& m, const box3& to, double shift) {
    const double w = 0.9, x = 0.21, y = -0.3, z = 0.17;
    const double n = std::sqrt(w * w + x * x + y * y + z * z);
    const double q[4] = {w / n, x / n, y / n, z / n};
    const double r[3][3] = {
        {1 - 2 * (q[2] * q[2] + q[3] * q[3]), 2 * (q[1] * q[2] - q[3] * q[0]), 2 * (q[1] * q[3] + q[2] * q[0])},
        {2 * (q[1] * q[2] + q[3] * q[0]), 1 - 2 * (q[1] * q[1] + q[3] * q[3]), 2 * (q[2] * q[3] - q[1] * q[0])},
        {2 * (q[1] * q[3] - q[2] * q[0]), 2 * (q[2] * q[3] + q[1] * q[0]), 1 - 2 * (q[1] * q[1] + q[2] * q[2])}};
    const box3 from = bounds(m);
    const double scale = diagonal(to) / diagonal(from);
    io::polygon_soup s;
    for (auto v : tr::vertices(m)) {
        const auto p = tr::position(m, v);
        std::array<double, 3> d{}, o{};
        for (std::size_t k = 0; k < 3; ++k) d[k] = (double(p[k]) - 0.5 * (from[0][k] + from[1][k])) * scale;
        for (std::size_t k = 0; k < 3; ++k)
            o[k] = 0.5 * (to[0][k] + to[1][k]) + r[k][0] * d[0] + r[k][1] * d[1] + r[k][2] * d[2] +
                   shift * (to[1][k] - to[0][k]) * (1.0 + 0.1 * double(k));
        s.points.push_back(o);
    }
    for (auto f : tr::faces(m)) {
        for (auto v : tr::face_vertices(m, f)) s.indices.push_back(std::uint32_t(tr::vertex_index(m, v)));
        s.face_offsets.push_back(s.indices.size());
    }
    mesh out;
    if (!detail::copy::build<mesh, tr>(out, s)) std::fprintf(stderr, "build failed\n");
    return out;
}

bool closed(const mesh& m) {
    std::map<std::array<std::size_t, 2>, int> count;
    for (auto f : tr::faces(m)) {
        std::vector<std::size_t> loop;
        for (auto v : tr::face_vertices(m, f)) loop.push_back(tr::vertex_index(m, v));
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const std::size_t a = loop[i], b = loop[(i + 1) % loop.size()];
            count[{std::min(a, b), std::max(a, b)}] += a < b ? 1 : -1;
        }
    }
    return !count.empty() && std::all_of(count.begin(), count.end(), [](const auto& e) { return e.second == 0; });
}

double volume(const mesh& m) {
    double vol = 0;
    for (auto f : tr::faces(m)) {
        std::vector<std::array<double, 3>> p;
        for (auto v : tr::face_vertices(m, f)) {
            const auto q = tr::position(m, v);
            p.push_back({double(q[0]), double(q[1]), double(q[2])});
        }
        for (std::size_t i = 1; i + 1 < p.size(); ++i) {
            const auto &a = p[0], &b = p[i], &c = p[i + 1];
            vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
                    a[2] * (b[0] * c[1] - b[1] * c[0])) /
                   6.0;
        }
    }
    return vol;
}

/// Empty when the pair passes, else what failed.
std::string check_pair(const mesh& a, const mesh& b) {
    const double va = volume(a), vb = volume(b);
    double vol[3] = {0, 0, 0};
    const boolean_op ops[3] = {boolean_op::union_, boolean_op::intersection, boolean_op::difference};
    const char* names[3] = {"union", "intersection", "difference"};
    for (int k = 0; k < 3; ++k) {
        mesh out;
        auto r = mesh_boolean(out, a, b, {.op = ops[k]});
        if (!r) return std::string(names[k]) + ": " + r.error().message;
        if (!closed(out) && tr::face_count(out) != 0) return std::string(names[k]) + ": not closed";
        auto si = self_intersections(out);
        if (!si) return std::string(names[k]) + ": self_intersections failed";
        if (!si->empty() && si->size() != r->rounding_intersections)
            return std::string(names[k]) + ": " + std::to_string(si->size()) + " self-intersections, " +
                   std::to_string(r->rounding_intersections) + " reported";
        vol[k] = volume(out);
    }
    const double tol = 1e-9 * (std::fabs(va) + std::fabs(vb));
    if (std::fabs(vol[0] + vol[1] - va - vb) > tol) return "volume identity (union + intersection)";
    if (std::fabs(vol[2] - (va - vol[1])) > tol) return "volume identity (difference)";
    return {};
}

}  // namespace

int main(int argc, char** argv) {
    std::filesystem::path dir;
    if (argc > 1) {
        dir = argv[1];
    } else if (const char* env = std::getenv("HMIRA_TEST_DATA")) {
        dir = std::filesystem::path(env) / "meshes";
    } else {
        std::fprintf(stderr, "usage: %s [dir] [max_faces]  (or set HMIRA_TEST_DATA)\n", argv[0]);
        return 2;
    }
    const std::size_t max_faces = argc > 2 ? std::size_t(std::atoll(argv[2])) : 20000;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::vector<std::pair<std::string, mesh>> meshes;
    for (const auto& f : files) {
        hmira::halfedge_mesh h;
        if (!io::read_mesh(h, f)) continue;
        // mesh_boolean cuts polygons as triangulate_faces does; cut them first so that the input
        // volumes are those of the surfaces it works on (a non-planar polygon has no one volume).
        mesh m;
        if (!triangulate_faces(h) || !copy_mesh(h, m)) continue;
        if (tr::face_count(m) == 0 || tr::face_count(m) > max_faces || !closed(m)) continue;
        auto si = self_intersections(m);
        if (!si || !si->empty()) continue;
        if (volume(m) <= 0) continue;  // inward-wound
        meshes.emplace_back(f.filename().string(), std::move(m));
    }
    std::printf("%zu closed, self-intersection-free, outward meshes of at most %zu faces\n", meshes.size(), max_faces);
    std::size_t pass = 0, total = 0;
    for (std::size_t i = 0; i < meshes.size(); ++i) {
        const auto& [name, m] = meshes[i];
        const std::size_t j = (i + 1) % meshes.size();
        const std::pair<std::string, mesh> others[2] = {{name, moved(m, bounds(m), 0.15)},
                                                        {meshes[j].first, moved(meshes[j].second, bounds(m), 0.2)}};
        for (const auto& [other, b] : others) {
            const auto t0 = std::chrono::steady_clock::now();
            const std::string why = check_pair(m, b);
            const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            ++total;
            pass += why.empty();
            std::printf("%-6s %s (%zu faces) x moved %s  %.2f s%s%s\n", why.empty() ? "pass" : "FAIL", name.c_str(),
                        tr::face_count(m), other.c_str(), s, why.empty() ? "" : "  ", why.c_str());
            std::fflush(stdout);
        }
    }
    std::printf("%zu of %zu pairs pass\n", pass, total);
    return pass == total ? 0 : 1;
}
