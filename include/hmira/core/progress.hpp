// hmira/core/progress.hpp
// How a long operation reports progress and lets its caller stop it: a callback the operation
// calls between blocks of work. The CLI's progress bar and the Python package's Ctrl-C use it.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <mutex>

namespace hmira {

/// Called between blocks of work with the fraction done, in [0, 1]. Returning false cancels
/// the operation: it stops at the next block boundary and returns an error whose message ends
/// in "cancelled", leaving its inputs and outputs untouched. Calls never overlap but may come
/// from any worker thread; a call that would overlap another is skipped, so a callback is not
/// called for every block. Leave it empty for none.
using progress_function = std::function<bool(double fraction_done)>;

namespace detail {

/// Shares one progress_function among the worker threads of one operation: counts the blocks
/// done, calls the function (never two calls at once) and remembers a cancellation.
class progress_gate {
public:
    /// `total` blocks make up the whole operation (0 is treated as 1).
    progress_gate(const progress_function& report, std::size_t total) : report_(report), total_(total ? total : 1) {}

    /// Records `blocks` more blocks done and reports; false once the operation is cancelled
    /// (by this call or an earlier one). O(1) plus the callback's own cost.
    bool advance(std::size_t blocks = 1) {
        if (cancelled_.load(std::memory_order_relaxed)) return false;
        if (!report_) return true;
        const std::size_t done = done_.fetch_add(blocks, std::memory_order_relaxed) + blocks;
        std::unique_lock lock(calling_, std::try_to_lock);
        if (!lock.owns_lock()) return true;  // another thread is reporting right now
        const double fraction = done >= total_ ? 1.0 : double(done) / double(total_);
        if (!report_(fraction)) cancelled_.store(true, std::memory_order_relaxed);
        return !cancelled_.load(std::memory_order_relaxed);
    }

    /// True once the callback has returned false.
    bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

private:
    const progress_function& report_;
    std::size_t total_;
    std::atomic<std::size_t> done_{0};
    std::atomic<bool> cancelled_{false};
    std::mutex calling_;
};

}  // namespace detail
}  // namespace hmira
