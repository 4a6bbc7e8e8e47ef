// hmira/meshes/detail/element_range.hpp
// The ranges hmira's meshes hand out: all live elements of a kind, and loops that follow a
// step function (around a face, around a vertex). They hold a pointer to the mesh, never to a
// temporary, so they stay valid while the mesh's connectivity is unchanged.
//
// They derive from std::ranges::view_base, not view_interface: clang 14 with libstdc++ 12
// substitutes view_interface's constrained members (data(), size()) while the derived class is
// still incomplete, and rejects every class derived from it. view_base keeps them views (so
// views::transform/filter take them by value); empty(), operator bool and front() are spelt
// out below in place of the ones view_interface would add.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <ranges>
#include <type_traits>
#include <utility>

namespace hmira::detail {

/// Handles [0, bound) skipping those whose flag deleted[i >> Shift] is set (deleted may be
/// null: none deleted). Shift 1 serves halfedges, which share their edge's flag.
template <class Handle, unsigned Shift = 0>
class element_range : public std::ranges::view_base {
public:
    class iterator {
    public:
        using value_type = Handle;
        using difference_type = std::ptrdiff_t;
        using iterator_concept = std::forward_iterator_tag;

        iterator() = default;
        iterator(std::uint32_t i, std::uint32_t bound, const std::uint8_t* deleted)
            : i_(i), bound_(bound), deleted_(deleted) {
            skip();
        }

        Handle operator*() const noexcept { return Handle(i_); }
        iterator& operator++() noexcept {
            ++i_;
            skip();
            return *this;
        }
        iterator operator++(int) noexcept {
            auto t = *this;
            ++*this;
            return t;
        }
        friend bool operator==(const iterator& a, const iterator& b) noexcept { return a.i_ == b.i_; }

    private:
        void skip() noexcept {
            if (deleted_)
                while (i_ < bound_ && deleted_[i_ >> Shift]) ++i_;
        }
        std::uint32_t i_ = 0, bound_ = 0;
        const std::uint8_t* deleted_ = nullptr;
    };

    element_range() = default;
    element_range(std::uint32_t bound, const std::uint8_t* deleted) : bound_(bound), deleted_(deleted) {}
    iterator begin() const { return iterator(0, bound_, deleted_); }
    iterator end() const { return iterator(bound_, bound_, nullptr); }
    bool empty() const { return begin() == end(); }
    explicit operator bool() const { return !empty(); }
    Handle front() const { return *begin(); }

private:
    std::uint32_t bound_ = 0;
    const std::uint8_t* deleted_ = nullptr;
};

/// Whether a loop policy filters: it has keep(mesh, cursor), and the loop then yields only
/// the cursors it keeps.
template <class Policy, class Mesh, class Cursor>
concept filtering_policy = requires(const Mesh& m, Cursor c) {
    { Policy::keep(m, c) } -> std::convertible_to<bool>;
};

/// A closed loop: starts at `start`, steps with Policy::step(mesh, h) until back at start, and
/// yields Policy::value(mesh, h) for each h (only those with Policy::keep(mesh, h), if the
/// policy has keep). An empty loop if start is null. A guard stops after `max_steps` so that
/// corrupt connectivity cannot hang a query. A position is the cursor and whether the lap is
/// done; the end is (start, done). ++ sets both when the step returns to start, so the
/// compiler folds the end test into that one comparison, as in a hand-written do-while. (An
/// end at the null cursor needed a second test per step, as the new cursor might be null:
/// three branches per step with the guard, and rings ran 1.05-1.1x a hand-written walk.)
template <class Mesh, class Cursor, class Policy>
class loop_range : public std::ranges::view_base {
public:
    class iterator {
    public:
        using value_type = std::remove_cvref_t<decltype(Policy::value(std::declval<const Mesh&>(), Cursor{}))>;
        using difference_type = std::ptrdiff_t;
        using iterator_concept = std::forward_iterator_tag;

        iterator() = default;
        iterator(const Mesh* m, Cursor start, Cursor cur, bool done) : m_(m), start_(start), cur_(cur), done_(done) {}

        value_type operator*() const { return Policy::value(*m_, cur_); }
        iterator& operator++() {
            do {
                cur_ = Policy::step(*m_, cur_);
                if (cur_ == start_ || ++steps_ > max_steps) {
                    cur_ = start_;
                    done_ = true;
                    break;
                }
            } while (!kept());
            return *this;
        }
        iterator operator++(int) {
            auto t = *this;
            ++*this;
            return t;
        }
        friend bool operator==(const iterator& a, const iterator& b) noexcept {
            return a.done_ == b.done_ && a.cur_ == b.cur_;
        }
        /// The current cursor (the loop's start at the end).
        Cursor cursor() const noexcept { return cur_; }

    private:
        bool kept() const {
            if constexpr (filtering_policy<Policy, Mesh, Cursor>)
                return Policy::keep(*m_, cur_);
            else
                return true;
        }
        const Mesh* m_ = nullptr;
        Cursor start_{}, cur_{};
        bool done_ = false;
        std::uint32_t steps_ = 0;
    };

    loop_range() = default;
    loop_range(const Mesh& m, Cursor start) : m_(&m), start_(start) {}
    iterator begin() const {
        // A filtering loop starts at its first kept cursor, found here rather than by the
        // iterator (which kept the hot ++ loop from being optimised as well at -O3).
        if constexpr (filtering_policy<Policy, Mesh, Cursor>) {
            if (start_ == Cursor{}) return end();
            Cursor first = start_;
            for (std::uint32_t steps = 0; !Policy::keep(*m_, first);) {
                first = Policy::step(*m_, first);
                if (first == start_ || ++steps > max_steps) return end();
            }
            return iterator(m_, start_, first, false);
        } else {
            return iterator(m_, start_, start_, start_ == Cursor{});  // the end already when start is null
        }
    }
    iterator end() const { return iterator(m_, start_, start_, true); }
    bool empty() const { return begin() == end(); }
    explicit operator bool() const { return !empty(); }
    auto front() const { return *begin(); }

private:
    static constexpr std::uint32_t max_steps = 1u << 30;
    const Mesh* m_ = nullptr;
    Cursor start_{};
};

/// A closed loop of a user's mesh (CGAL, OpenMesh) from `start`, stepping with Policy::step
/// until back at start and yielding Policy::value of each; empty if start is the null cursor.
/// The position is the cursor and a lap count, the end being (start, lap 1), as in those
/// libraries' own circulators: ++ only tests the new cursor against start, and the compiler
/// folds the end test into that one comparison. Unlike loop_range it has no step guard, as
/// their circulators have none: a guard costs a comparison per step, which keeps the ring
/// slower than those libraries' native circulation. Corrupt links that never return to start
/// loop for ever here, as they do in the library's own code; hmira::validate stops on such a
/// loop and names it.
template <class Mesh, class Cursor, class Policy>
class lap_range : public std::ranges::view_base {
public:
    class iterator {
    public:
        using value_type = std::remove_cvref_t<decltype(Policy::value(std::declval<const Mesh&>(), Cursor{}))>;
        using difference_type = std::ptrdiff_t;
        using iterator_concept = std::forward_iterator_tag;
        iterator() = default;
        iterator(const Mesh* m, Cursor start, Cursor cur, int lap) : m_(m), start_(start), cur_(cur), lap_(lap) {}
        value_type operator*() const { return Policy::value(*m_, cur_); }
        iterator& operator++() {
            cur_ = Policy::step(*m_, cur_);
            if (cur_ == start_) ++lap_;
            return *this;
        }
        iterator operator++(int) {
            auto t = *this;
            ++*this;
            return t;
        }
        friend bool operator==(const iterator& a, const iterator& b) noexcept {
            return a.lap_ == b.lap_ && a.cur_ == b.cur_;
        }

    private:
        const Mesh* m_ = nullptr;
        Cursor start_{}, cur_{};
        int lap_ = 0;
    };
    lap_range() = default;
    lap_range(const Mesh& m, Cursor start) : m_(&m), start_(start) {}
    iterator begin() const { return iterator(m_, start_, start_, start_ == Cursor{} ? 1 : 0); }
    iterator end() const { return iterator(m_, start_, start_, 1); }
    bool empty() const { return start_ == Cursor{}; }
    explicit operator bool() const { return !empty(); }
    auto front() const { return *begin(); }

private:
    const Mesh* m_ = nullptr;
    Cursor start_{};
};

}  // namespace hmira::detail

// Both ranges only refer to the mesh, so iterators obtained from a temporary range stay valid.
template <class Handle, unsigned Shift>
inline constexpr bool std::ranges::enable_borrowed_range<hmira::detail::element_range<Handle, Shift>> = true;
template <class Mesh, class Cursor, class Policy>
inline constexpr bool std::ranges::enable_borrowed_range<hmira::detail::loop_range<Mesh, Cursor, Policy>> = true;
template <class Mesh, class Cursor, class Policy>
inline constexpr bool std::ranges::enable_borrowed_range<hmira::detail::lap_range<Mesh, Cursor, Policy>> = true;
