// hmira/io/detail/files.hpp
// File plumbing shared by the readers and writers: whole-file input through mmap (no copy,
// no iostream), clear errors for missing files and directories, and atomic writes
// (temporary file in the same folder, then rename) so that a failed write never truncates
// or replaces an existing file.
#pragma once

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>

#include "../../core/result.hpp"
#include "atomic_write.hpp"

namespace hmira::io::detail {

/// A read-only view of a whole file: memory-mapped when it is a regular file, read into a
/// buffer otherwise (pipes, /dev/stdin). Move-only.
class input_file {
public:
    input_file() = default;
    input_file(const input_file&) = delete;
    input_file& operator=(const input_file&) = delete;
    input_file(input_file&& o) noexcept { swap(o); }
    input_file& operator=(input_file&& o) noexcept {
        if (this != &o) {
            release();
            swap(o);
        }
        return *this;
    }
    ~input_file() { release(); }

    std::string_view text() const noexcept { return map_ ? std::string_view(static_cast<const char*>(map_), size_) : std::string_view(buffer_); }

    static result<input_file> open(const std::filesystem::path& path) {
        const std::string name = path.string();
        struct stat st{};
        if (::stat(name.c_str(), &st) != 0)
            return fail(errc::io_error, name + ": cannot open: " + std::strerror(errno));
        if (S_ISDIR(st.st_mode)) return fail(errc::io_error, name + ": is a directory, not a mesh file");
        const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0) return fail(errc::io_error, name + ": cannot open: " + std::strerror(errno));
        input_file f;
        if (S_ISREG(st.st_mode) && st.st_size > 0) {
            void* m = ::mmap(nullptr, static_cast<std::size_t>(st.st_size), PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
            if (m != MAP_FAILED) {
                ::madvise(m, static_cast<std::size_t>(st.st_size), MADV_SEQUENTIAL);
                f.map_ = m;
                f.size_ = static_cast<std::size_t>(st.st_size);
                ::close(fd);
                return f;
            }
        }
        char chunk[1 << 16];
        for (;;) {
            const auto n = ::read(fd, chunk, sizeof chunk);
            if (n < 0) {
                if (errno == EINTR) continue;
                const std::string why = std::strerror(errno);
                ::close(fd);
                return fail(errc::io_error, name + ": read error: " + why);
            }
            if (n == 0) break;
            f.buffer_.append(chunk, static_cast<std::size_t>(n));
        }
        ::close(fd);
        return f;
    }

private:
    void release() noexcept {
        if (map_) ::munmap(map_, size_);
        map_ = nullptr;
        size_ = 0;
    }
    void swap(input_file& o) noexcept {
        std::swap(map_, o.map_);
        std::swap(size_, o.size_);
        std::swap(buffer_, o.buffer_);
    }
    void* map_ = nullptr;
    std::size_t size_ = 0;
    std::string buffer_;
};

/// The whole file as a string (small files, tests). Prefer input_file for meshes.
inline result<std::string> read_file(const std::filesystem::path& path) {
    auto f = input_file::open(path);
    if (!f) return f.error();
    return std::string(f->text());
}

/// Collects output in memory and hands it to the stream in large blocks, so writers format
/// numbers into a string without an iostream call per number.
class chunked_output {
public:
    explicit chunked_output(std::ostream& out) : out_(out) { buf_.reserve(limit + 4096); }
    std::string& buffer() noexcept { return buf_; }
    /// Call after each record: flushes once the buffer is large.
    bool maybe_flush() {
        if (buf_.size() < limit) return true;
        return flush();
    }
    bool flush() {
        if (!buf_.empty()) out_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
        buf_.clear();
        return static_cast<bool>(out_);
    }

private:
    static constexpr std::size_t limit = 1 << 20;
    std::ostream& out_;
    std::string buf_;
};

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
    /// Byte offset of the next line's start.
    std::size_t position() const noexcept { return pos_ < text_.size() ? pos_ : text_.size(); }

private:
    std::string_view text_;
    std::size_t pos_ = 0, line_no_ = 0;
};

/// Splits off the next whitespace-separated token of `s`.
inline std::string_view next_token(std::string_view& s) {
    std::size_t i = 0;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < s.size() && s[j] != ' ' && s[j] != '\t' && s[j] != '\r') ++j;
    const auto tok = s.substr(i, j - i);
    s.remove_prefix(j);
    return tok;
}

}  // namespace hmira::io::detail
