// hmira/core/progress.hpp
// How a long operation reports progress and lets its caller stop it: a callback the operation
// calls between blocks of work. The CLI's progress bar and the Python package's Ctrl-C use it.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>

#include "result.hpp"

namespace hmira {

/// Called between blocks of work with the fraction done, in [0, 1]. Returning false cancels
/// the operation: it stops at the next block boundary and returns an error whose message ends
/// in "cancelled", leaving its inputs and outputs untouched. Calls never overlap but may come
/// from any worker thread; a call that would overlap another is skipped, so a callback is not
/// called for every block. Leave it empty for none.
using progress_function = std::function<bool(double fraction_done)>;

namespace detail {

/// Shares one progress_function among the worker threads of one operation: counts the blocks
/// done, calls the function (never two calls at once) and remembers a cancellation. The
/// fraction it reports never goes backwards.
///
/// An operation that counts single elements on one thread (an edit stepping through the
/// elements it builds) calls step() per element instead of advance(): the gate then reports
/// once every `step_block` elements, so the per-element cost is a counter increment, and a
/// cancellation becomes an errc::cancelled error naming the operation.
class progress_gate {
public:
    /// Elements step() counts between two reports.
    static constexpr std::size_t step_block = 1024;

    /// `total` blocks make up the whole operation (0 is treated as 1). `what` names the
    /// operation in step()'s cancellation error ("<what>: cancelled").
    progress_gate(const progress_function& report, std::size_t total, const char* what = "operation")
        : report_(report), total_(total ? total : 1), what_(what) {}

    /// Records `blocks` more blocks done and reports; false once the operation is cancelled
    /// (by this call or an earlier one). O(1) plus the callback's own cost.
    bool advance(std::size_t blocks = 1) {
        if (cancelled_.load(std::memory_order_relaxed)) return false;
        if (!report_) return true;
        const std::size_t done = done_.fetch_add(blocks, std::memory_order_relaxed) + blocks;
        std::unique_lock lock(calling_, std::try_to_lock);
        if (!lock.owns_lock()) return true;  // another thread is reporting right now
        // Never backwards: add_work() may grow the total after some reports.
        const double fraction = done >= total_ ? 1.0 : double(done) / double(total_);
        if (fraction > reported_) reported_ = fraction;
        if (!report_(reported_)) cancelled_.store(true, std::memory_order_relaxed);
        return !cancelled_.load(std::memory_order_relaxed);
    }

    /// Counts one element done, from the one thread that does the work; every step_block
    /// elements, advances the gate by as many. An errc::cancelled error "<what>: cancelled" once
    /// the callback has asked to stop; the caller returns it (and rolls back what it changed).
    /// O(1) except at the end of a block, where it adds the callback's own cost.
    result<void> step() {
        if (!report_ || ++stepped_ % step_block != 0) return {};
        if (!advance(step_block)) return fail(errc::cancelled, std::string(what_) + ": cancelled");
        return {};
    }

    /// Adds `blocks` to the total, for an operation that learns its size phase by phase (bevel
    /// plans before it builds), so that every phase can report and be cancelled. Not
    /// concurrently with advance().
    void add_work(std::size_t blocks) { total_ += blocks; }

    /// True once the callback has returned false.
    bool cancelled() const noexcept { return cancelled_.load(std::memory_order_relaxed); }

private:
    const progress_function& report_;
    std::size_t total_;
    const char* what_;
    std::atomic<std::size_t> done_{0};
    std::size_t stepped_ = 0;
    double reported_ = 0;  // the last fraction reported, under calling_
    std::atomic<bool> cancelled_{false};
    std::mutex calling_;
};

}  // namespace detail
}  // namespace hmira
