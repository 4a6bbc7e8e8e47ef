// hmira/io/detail/files.hpp
// File plumbing shared by the readers and writers: whole-file input (read once, bounded, safe
// against a file that shrinks underneath), clear errors for missing files and directories,
// and text helpers; atomic writes live in atomic_write.hpp.
#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
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

#include "../../core/huge_pages.hpp"
#include "../../core/result.hpp"
#include "atomic_write.hpp"

namespace hmira::io::detail {

/// Largest input read from a non-regular file when the caller gives no limit (4 GiB).
inline constexpr std::uint64_t default_max_input_bytes = std::uint64_t{4} << 30;

/// Test hook: when set, input_file::open calls it with the path after it has learnt the
/// size of a regular file and before it reads the bytes, so that a test can shrink the file
/// in between (what another process may do at any time).
inline void (*input_file_size_known_hook)(const char* path) = nullptr;

/// A growable byte array on malloc/realloc. glibc moves a large block with mremap, so
/// growing it copies nothing and costs no more memory than the bytes it holds. Move-only.
class byte_buffer {
public:
    byte_buffer() = default;
    byte_buffer(const byte_buffer&) = delete;
    byte_buffer& operator=(const byte_buffer&) = delete;
    byte_buffer(byte_buffer&& o) noexcept { swap(o); }
    byte_buffer& operator=(byte_buffer&& o) noexcept {
        if (this != &o) {
            byte_buffer().swap(*this);
            swap(o);
        }
        return *this;
    }
    ~byte_buffer() { std::free(data_); }

    char* data() noexcept { return data_; }
    const char* data() const noexcept { return data_; }
    std::size_t size() const noexcept { return size_; }
    std::size_t capacity() const noexcept { return capacity_; }
    std::string_view view() const noexcept { return {data_ ? data_ : "", size_}; }
    /// Room for at least `n` bytes; false (and unchanged) when memory runs out.
    bool reserve(std::size_t n) noexcept {
        if (n <= capacity_) return true;
        void* p = std::realloc(data_, n);
        if (!p) return false;
        data_ = static_cast<char*>(p);
        capacity_ = n;
        hmira::detail::advise_huge_pages(data_, capacity_);  // read(2) fills it next: fewer page faults
        return true;
    }
    /// Declares the first `n` <= capacity() bytes written.
    void set_size(std::size_t n) noexcept { size_ = n; }
    /// Grows the capacity geometrically, but never past `limit` bytes; false when at the
    /// limit already or out of memory.
    bool grow_towards(std::size_t limit) noexcept {
        if (capacity_ >= limit) return false;
        const std::size_t want =
            capacity_ < limit / 2 ? std::max<std::size_t>(2 * capacity_, std::size_t{1} << 16) : limit;
        return reserve(std::min(want, limit));
    }
    void swap(byte_buffer& o) noexcept {
        std::swap(data_, o.data_);
        std::swap(size_, o.size_);
        std::swap(capacity_, o.capacity_);
    }

private:
    char* data_ = nullptr;
    std::size_t size_ = 0, capacity_ = 0;
};

/// A whole file in memory, read once with read(2). Reading (rather than memory-mapping)
/// means a file truncated by another process while we read it gives an error, never a
/// SIGBUS; the copy costs a few percent of a parse. A regular file is read up to the size
/// it had when opened; any other file (pipe, FIFO, device) up to a limit. Move-only.
class input_file {
public:
    /// The bytes.
    std::string_view text() const noexcept { return bytes_.view(); }

    /// Reads the file at `path`. A non-regular file longer than `max_bytes` is an error.
    /// Errors: io_error for a missing file, a directory, a read error, a regular file that
    /// shrank while being read, or a non-regular file longer than `max_bytes`.
    static result<input_file> open(const std::filesystem::path& path,
                                   std::uint64_t max_bytes = default_max_input_bytes) {
        const std::string name = path.string();
        const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
        if (fd < 0) return fail(errc::io_error, name + ": cannot open: " + std::strerror(errno));
        struct closer {
            int fd;
            ~closer() { ::close(fd); }
        } close_fd{fd};
        struct stat st {};
        if (::fstat(fd, &st) != 0) return fail(errc::io_error, name + ": cannot open: " + std::strerror(errno));
        if (S_ISDIR(st.st_mode)) return fail(errc::io_error, name + ": is a directory, not a mesh file");
        input_file f;
        auto& b = f.bytes_;
        // (A regular file of size 0 may still have content, as /proc files do: read it as a stream.)
        if (S_ISREG(st.st_mode) && st.st_size > 0) {
            const auto size = static_cast<std::uint64_t>(st.st_size);
            if (input_file_size_known_hook) input_file_size_known_hook(name.c_str());
            if (size > SIZE_MAX || !b.reserve(static_cast<std::size_t>(size)))
                return fail(errc::io_error,
                            name + ": not enough memory to read its " + std::to_string(size) + " bytes");
            while (b.size() < size) {
                const auto n = ::read(fd, b.data() + b.size(), static_cast<std::size_t>(size - b.size()));
                if (n < 0 && errno == EINTR) continue;
                if (n < 0) return fail(errc::io_error, name + ": read error: " + std::strerror(errno));
                if (n == 0)
                    return fail(errc::io_error, name + ": file shrank while reading (" + std::to_string(size) +
                                                    " bytes when opened, " + std::to_string(b.size()) + " read)");
                b.set_size(b.size() + static_cast<std::size_t>(n));
            }
            return f;
        }
        // A pipe or device: read until its end, but never more than one byte past the limit.
        const std::size_t limit = static_cast<std::size_t>(std::min<std::uint64_t>(max_bytes, SIZE_MAX - 1) + 1);
        for (;;) {
            if (b.size() == b.capacity()) {
                if (b.size() > max_bytes)
                    return fail(errc::unsupported, name + ": not a regular file, and longer than the input limit of " +
                                                       std::to_string(max_bytes) + " bytes (max_input_bytes)");
                if (!b.grow_towards(limit))
                    return fail(errc::io_error, name + ": not enough memory to read it (" + std::to_string(b.size()) +
                                                    " bytes so far)");
            }
            const auto n = ::read(fd, b.data() + b.size(), b.capacity() - b.size());
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) return fail(errc::io_error, name + ": read error: " + std::strerror(errno));
            if (n == 0) break;
            b.set_size(b.size() + static_cast<std::size_t>(n));
        }
        return f;
    }

private:
    byte_buffer bytes_;
};

/// The whole file as a string (small files, tests). Prefer input_file for meshes.
inline result<std::string> read_file(const std::filesystem::path& path,
                                     std::uint64_t max_bytes = default_max_input_bytes) {
    auto f = input_file::open(path, max_bytes);
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
