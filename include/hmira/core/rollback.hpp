// hmira/core/rollback.hpp
// How a whole-mesh rewrite leaves the mesh as it found it when it fails or is cancelled after
// its first change: it saves what it rewrites before that change, and puts it back unless it
// commits. Local edits built from the Euler operators use the editing journal instead
// (algorithms/editing/detail/transaction.hpp); docs/new-algorithm.md gives the rule.
#pragma once

#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

#include "vec3.hpp"

namespace hmira {

/// A copy of a mesh, taken when a rewrite can still stop after its first change, and put back
/// into the mesh by restore() or by the destructor unless commit() came first. Armed with
/// `needed = false` it holds nothing and costs nothing: pass false exactly when nothing can
/// stop the rewrite once it has begun (no progress callback and no failure after the checks).
///
///     mesh_rollback<M> undo(mesh, bool(options.progress));
///     ... change the mesh; `return fail(errc::cancelled, ...)` puts it back ...
///     undo.commit();
///
/// \post after restore() or a destruction without commit(), the mesh is the copy: every
/// element, link, position, index bound and property as they were when the rollback was made.
/// Complexity O(V + E + F) time and memory for the copy when armed, O(1) otherwise; restore()
/// is a move assignment.
template <class M>
class mesh_rollback {
public:
    /// Copies `mesh` when `needed`.
    mesh_rollback(M& mesh, bool needed) : mesh_(mesh) {
        if (needed) copy_.emplace(mesh);
    }
    ~mesh_rollback() { restore(); }
    mesh_rollback(const mesh_rollback&) = delete;
    mesh_rollback& operator=(const mesh_rollback&) = delete;

    /// Whether a copy is held (it was taken and neither restored nor committed yet).
    bool armed() const noexcept { return copy_.has_value(); }

    /// Puts the copy back into the mesh, if one is held, and drops it.
    void restore() {
        if (!copy_) return;
        mesh_ = std::move(*copy_);
        copy_.reset();
    }

    /// The rewrite succeeded: drops the copy, keeping the mesh as it is now.
    void commit() noexcept { copy_.reset(); }

private:
    M& mesh_;
    std::optional<M> copy_;
};

/// The same rule for a rewrite that only moves vertices (smoothing): it saves the positions
/// alone, by vertex index, as doubles (exact for float and double scalars), and puts back those
/// of the vertices `moves` selects. A rewrite that reads the starting positions anyway reads
/// them from positions(), so the rollback costs no extra pass.
///
/// \post after restore() or a destruction without commit(), every position is as it was, bit
/// for bit; the connectivity was never touched.
/// Complexity O(V) time and 24 bytes per vertex index to save and to restore.
template <class M, class T>
class position_rollback {
public:
    /// Saves every vertex's position.
    explicit position_rollback(M& mesh) : mesh_(mesh) {
        saved_.resize(T::vertex_index_bound(mesh));
        for (auto v : T::vertices(mesh)) {
            const vec3<typename T::scalar> p = T::position(mesh, v);
            saved_[T::vertex_index(mesh, v)] = {double(p.x), double(p.y), double(p.z)};
        }
    }
    ~position_rollback() { restore(); }
    position_rollback(const position_rollback&) = delete;
    position_rollback& operator=(const position_rollback&) = delete;

    /// The saved positions, by vertex index.
    const std::vector<vec3<double>>& positions() const noexcept { return saved_; }

    /// Limits restore() to the vertices whose index `moves(i)` holds for (the others were
    /// never written). Without it every vertex is restored.
    template <class Pred>
    void restore_only(Pred&& moves) {
        if (committed_) return;
        using S = typename T::scalar;
        for (auto v : T::vertices(mesh_)) {
            const std::size_t i = T::vertex_index(mesh_, v);
            if (!moves(i)) continue;
            const auto& p = saved_[i];
            T::set_position(mesh_, v, vec3<S>{S(p.x), S(p.y), S(p.z)});
        }
        committed_ = true;
    }

    /// Puts every saved position back, once.
    void restore() {
        restore_only([](std::size_t) { return true; });
    }

    /// The rewrite succeeded: the positions stay as they are now.
    void commit() noexcept { committed_ = true; }

private:
    M& mesh_;
    std::vector<vec3<double>> saved_;
    bool committed_ = false;
};

}  // namespace hmira
