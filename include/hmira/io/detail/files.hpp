// hmira/io/detail/files.hpp
// File plumbing shared by the readers and writers: whole-file reads with clear errors, and
// atomic writes (temporary file in the same folder, then rename) so that a failed write never
// truncates or replaces an existing file.
#pragma once

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <system_error>

#include "../../core/result.hpp"

namespace hmira::io::detail {

inline result<std::string> read_file(const std::filesystem::path& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        return fail(errc::io_error, path.string() + ": is a directory, not a mesh file");
    std::ifstream in(path, std::ios::binary);
    if (!in) return fail(errc::io_error, path.string() + ": cannot open for reading");
    std::ostringstream ss;
    ss << in.rdbuf();
    if (in.bad()) return fail(errc::io_error, path.string() + ": read error");
    return std::move(ss).str();
}

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
        if (!ok || !out) {
            out.close();
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

/// A line-oriented cursor over text with 1-based line numbers, for file:line messages.
class line_reader {
public:
    explicit line_reader(std::string_view text) : text_(text) {}
    bool next(std::string_view& line) {
        if (pos_ >= text_.size()) return false;
        const auto end = text_.find('\n', pos_);
        const auto stop = end == std::string_view::npos ? text_.size() : end;
        line = text_.substr(pos_, stop - pos_);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        pos_ = stop + 1;
        ++line_no_;
        return true;
    }
    std::size_t line_number() const noexcept { return line_no_; }

private:
    std::string_view text_;
    std::size_t pos_ = 0, line_no_ = 0;
};

/// Splits off the next whitespace-separated token of `s`.
inline std::string_view next_token(std::string_view& s) {
    std::size_t i = 0;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t') ++j;
    const auto tok = s.substr(i, j - i);
    s.remove_prefix(j);
    return tok;
}

}  // namespace hmira::io::detail
