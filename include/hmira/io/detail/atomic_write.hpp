// hmira/io/detail/atomic_write.hpp
// Atomic file output for every writer: the bytes go to a temporary file in the same folder,
// which replaces the target only once complete, so a failed or interrupted write never
// truncates or replaces an existing file, nor leaves the temporary behind.
#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <filesystem>
#include <memory>
#include <ostream>
#include <random>
#include <streambuf>
#include <string>
#include <system_error>
#include <utility>

#include "../../core/result.hpp"

namespace hmira::io::detail {

/// A temporary file that exists under a name right now (the fallback without O_TMPFILE, and
/// the moment between linking and renaming), recorded where a signal handler can read it.
struct live_temporary {
    std::atomic<int> state{0};  ///< 0 free, 1 being recorded, 2 `path` names a file to remove on a signal
    char path[4096]{};          ///< NUL-terminated
};
/// How many writes at once can record their temporary (one is usual; more are still written,
/// only without the signal-time cleanup).
inline constexpr std::size_t max_live_temporaries = 16;
/// The record. Constant-initialised, so a signal handler may read it at any time.
inline live_temporary live_temporaries[max_live_temporaries];

/// Records `path` as a live temporary; returns its slot, or -1 if the record is full or the
/// path too long.
inline int register_temporary(const std::string& path) noexcept {
    if (path.size() >= sizeof(live_temporaries[0].path)) return -1;
    for (std::size_t i = 0; i < max_live_temporaries; ++i) {
        int expected = 0;
        if (!live_temporaries[i].state.compare_exchange_strong(expected, 1, std::memory_order_acquire)) continue;
        std::memcpy(live_temporaries[i].path, path.c_str(), path.size() + 1);
        live_temporaries[i].state.store(2, std::memory_order_release);
        return static_cast<int>(i);
    }
    return -1;
}

/// Forgets a slot from register_temporary() (-1 is ignored).
inline void unregister_temporary(int slot) noexcept {
    if (slot >= 0) live_temporaries[slot].state.store(0, std::memory_order_release);
}

/// Removes every recorded temporary. Async-signal-safe (atomic loads and unlink only): meant
/// for a program's SIGINT/SIGTERM/SIGHUP handler, which the library does not install.
inline void unlink_live_temporaries() noexcept {
    for (auto& t : live_temporaries)
        if (t.state.load(std::memory_order_acquire) == 2) ::unlink(t.path);
}

/// Test hooks of the writers (all off by default).
struct atomic_write_hooks {
    /// Called once, after the first chunk of a temporary reaches the file.
    void (*after_first_chunk)() = nullptr;
    /// Never use O_TMPFILE: every temporary has a name (exercises the signal-time cleanup).
    bool named_temporary_only = false;
};
/// The hooks in force.
inline atomic_write_hooks write_hooks{};

/// An output buffer over a file descriptor that remembers the first write error (errno).
class fd_output_buffer : public std::streambuf {
public:
    explicit fd_output_buffer(int fd) : fd_(fd), buffer_(new char[size]) { setp(buffer_.get(), buffer_.get() + size); }
    /// errno of the first failed write, or 0.
    int error() const noexcept { return error_; }

protected:
    int_type overflow(int_type c) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(c, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(c);
            pbump(1);
        }
        return traits_type::not_eof(c);
    }
    int sync() override { return drain() ? 0 : -1; }

private:
    static constexpr std::size_t size = std::size_t{1} << 16;
    bool drain() {
        const char* p = pbase();
        std::size_t left = static_cast<std::size_t>(pptr() - pbase());
        while (left > 0 && error_ == 0) {
            const ::ssize_t n = ::write(fd_, p, left);
            if (n < 0) {
                if (errno != EINTR) error_ = errno;
                continue;
            }
            p += n;
            left -= static_cast<std::size_t>(n);
            if (!first_chunk_done_) {
                first_chunk_done_ = true;
                if (write_hooks.after_first_chunk) write_hooks.after_first_chunk();
            }
        }
        setp(buffer_.get(), buffer_.get() + size);
        return error_ == 0;
    }
    int fd_;
    std::unique_ptr<char[]> buffer_;
    int error_ = 0;
    bool first_chunk_done_ = false;
};

/// A complete temporary file waiting to replace `path`. commit() puts it in place; without a
/// commit the destructor removes it. Lets several files be written first and committed
/// together (a volume's data, then the sidecar describing it).
class staged_file {
public:
    /// Writes through `fill(std::ostream&)` (false: failed) into a temporary next to `path`:
    /// an unnamed O_TMPFILE where the file system has it (nothing is left even after SIGKILL),
    /// else a named one, recorded for unlink_live_temporaries(). The temporary's name is
    /// short whatever the target's length, so it fits NAME_MAX. `path` is not touched.
    template <class Fill>
    static result<staged_file> write(const std::filesystem::path& path, Fill&& fill) {
        namespace fs = std::filesystem;
        std::error_code ec;
        if (fs::is_directory(path, ec)) return fail(errc::io_error, path.string() + ": is a directory");
        staged_file s;
        s.path_ = path;
        s.dir_ = path.has_parent_path() ? path.parent_path() : fs::path(".");
        if (!fs::is_directory(s.dir_, ec))
            return fail(errc::io_error, path.string() + ": folder " + s.dir_.string() + " does not exist");
        if (auto opened = s.open_temporary(); !opened) return opened.error();
        fd_output_buffer buffer(s.fd_);
        std::ostream out(&buffer);
        const bool ok = fill(out);  // an exception leaves through ~staged_file, which removes the temporary
        out.flush();
        if (!ok || !out || buffer.error() != 0) {
            const std::string why =
                buffer.error() != 0 ? std::strerror(buffer.error()) : "the data could not be produced";
            return fail(errc::io_error, path.string() + ": write failed: " + why + "; the existing file is unchanged");
        }
        return s;
    }

    /// Replaces the target with the temporary (rename: readers see the old file or the new
    /// one, never a part). On failure the temporary is removed and the target is unchanged.
    result<void> commit() {
        namespace fs = std::filesystem;
        if (fd_ < 0 && temp_.empty()) return fail(errc::io_error, path_.string() + ": nothing to commit");
        if (temp_.empty()) {
            // An unnamed file gets a name only now, for the instant before the rename.
            if (auto named = link_unnamed(); !named) return named.error();
        }
        if (fd_ >= 0) {
            const int fd = std::exchange(fd_, -1);
            if (::close(fd) != 0) {
                const int e = errno;
                discard();
                return fail(errc::io_error, path_.string() + ": write failed: " + std::strerror(e) +
                                                "; the existing file is unchanged");
            }
        }
        if (::rename(temp_.c_str(), path_.c_str()) != 0) {
            const int e = errno;
            discard();
            return fail(errc::io_error, path_.string() + ": cannot replace the file: " + std::strerror(e));
        }
        unregister_temporary(std::exchange(slot_, -1));
        temp_.clear();
        return {};
    }

    staged_file(staged_file&& o) noexcept
        : path_(std::move(o.path_)),
          dir_(std::move(o.dir_)),
          fd_(std::exchange(o.fd_, -1)),
          temp_(std::move(o.temp_)),
          slot_(std::exchange(o.slot_, -1)) {
        o.temp_.clear();
    }
    staged_file& operator=(staged_file&&) = delete;
    staged_file(const staged_file&) = delete;
    staged_file& operator=(const staged_file&) = delete;
    ~staged_file() { discard(); }

private:
    staged_file() = default;

    /// ".tmp-<at most 64 bytes of the target's name>-<16 hex digits>": at most 86 bytes.
    std::string temporary_name() const {
        std::random_device rd;
        const unsigned long long r = (static_cast<unsigned long long>(rd()) << 32) ^ rd();
        char hex[17];
        for (int i = 0; i < 16; ++i) hex[i] = "0123456789abcdef"[(r >> (4 * (15 - i))) & 15];
        hex[16] = '\0';
        return (dir_ / (".tmp-" + path_.filename().string().substr(0, 64) + "-" + hex)).string();
    }

    result<void> open_temporary() {
#ifdef O_TMPFILE
        if (!write_hooks.named_temporary_only) {
            fd_ = ::open(dir_.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
            if (fd_ >= 0) return {};
        }
#endif
        int e = 0;
        for (int attempt = 0; attempt < 16; ++attempt) {
            std::string name = temporary_name();
            slot_ = register_temporary(name);  // before it exists: a signal must find it
            fd_ = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
            if (fd_ >= 0) {
                temp_ = std::move(name);
                return {};
            }
            e = errno;
            unregister_temporary(std::exchange(slot_, -1));
            if (e != EEXIST) break;
        }
        return fail(errc::io_error,
                    path_.string() + ": cannot create a temporary file in " + dir_.string() + ": " + std::strerror(e));
    }

    result<void> link_unnamed() {
        int e = 0;
        for (int attempt = 0; attempt < 16; ++attempt) {
            std::string name = temporary_name();
            slot_ = register_temporary(name);
            // /proc/self/fd works without privileges; AT_EMPTY_PATH needs CAP_DAC_READ_SEARCH.
            const std::string self = "/proc/self/fd/" + std::to_string(fd_);
            int linked = ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW);
            if (linked != 0 && errno != EEXIST) linked = ::linkat(fd_, "", AT_FDCWD, name.c_str(), AT_EMPTY_PATH);
            if (linked == 0) {
                temp_ = std::move(name);
                return {};
            }
            e = errno;
            unregister_temporary(std::exchange(slot_, -1));
            if (e != EEXIST) break;
        }
        discard();
        return fail(errc::io_error,
                    path_.string() + ": cannot name the temporary file in " + dir_.string() + ": " + std::strerror(e));
    }

    void discard() noexcept {
        if (fd_ >= 0) ::close(std::exchange(fd_, -1));
        if (!temp_.empty()) ::unlink(temp_.c_str());
        temp_.clear();
        unregister_temporary(std::exchange(slot_, -1));
    }

    std::filesystem::path path_, dir_;
    int fd_ = -1;       ///< the open temporary, until committed
    std::string temp_;  ///< the temporary's name, once it has one
    int slot_ = -1;     ///< its slot in live_temporaries
};

/// Writes through `fill(std::ostream&)` into a temporary file next to `path`, then renames it
/// over `path`. On any failure the temporary is removed and `path` is untouched.
template <class Fill>
result<void> write_file_atomically(const std::filesystem::path& path, Fill&& fill) {
    auto staged = staged_file::write(path, std::forward<Fill>(fill));
    if (!staged) return staged.error();
    return staged->commit();
}

}  // namespace hmira::io::detail
