// hmira/io/detail/atomic_write.hpp
// Atomic file output for every writer: the bytes go to a temporary file in the same folder,
// which is renamed over the target only once complete, so a failed write never truncates or
// replaces an existing file.
#pragma once

#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <system_error>

#include "../../core/result.hpp"

namespace hmira::io::detail {

/// Writes through `fill(std::ostream&)` into a temporary file next to `path`, then renames it
/// over `path`. On any failure the temporary is removed and `path` is untouched.
template <class Fill>
result<void> write_file_atomically(const std::filesystem::path& path, Fill&& fill) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(path, ec)) return fail(errc::io_error, path.string() + ": is a directory");
    const fs::path dir = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(dir, ec)) return fail(errc::io_error, path.string() + ": folder " + dir.string() + " does not exist");
    std::random_device rd;
    const fs::path tmp = dir / (".tmp-" + path.filename().string() + "-" + std::to_string(rd()));
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) return fail(errc::io_error, path.string() + ": cannot create a temporary file in " + dir.string());
        bool ok = true;
        try {
            ok = fill(out);
        } catch (...) {
            out.close();
            fs::remove(tmp, ec);
            throw;
        }
        out.flush();
        out.close();
        if (!ok || !out) {
            fs::remove(tmp, ec);
            return fail(errc::io_error, path.string() + ": write failed (disk full?); the existing file is unchanged");
        }
    }
    fs::rename(tmp, path, ec);
    if (ec) {
        fs::remove(tmp, ec);
        return fail(errc::io_error, path.string() + ": cannot replace the file: " + ec.message());
    }
    return {};
}

}  // namespace hmira::io::detail
