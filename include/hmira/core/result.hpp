// hmira/core/result.hpp
// A small std::expected stand-in: libstdc++ 12 ships std::expected only in C++23 mode and hmira
// is a C++20 library. Operations whose preconditions can fail at run time return result<T>;
// they never fail silently and leave the mesh unchanged on failure.
#pragma once

#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace hmira {

/// Why an operation refused to run. `element` is the index of the offending element when
/// there is one (for example the face index of a bad face), otherwise -1.
enum class errc {
    invalid_handle,        ///< a handle that is null, out of range, or deleted
    invalid_argument,      ///< an option or argument out of its documented range
    degenerate_face,       ///< fewer than 3 vertices, or a repeated vertex
    non_manifold,          ///< the operation would create a non-manifold edge or vertex
    orientation_conflict,  ///< the face's winding disagrees with a neighbour
    topology,              ///< a topological precondition failed (degree, boundary, ring...)
    io_error,              ///< reading or writing a file failed
    parse_error,           ///< a file's content is malformed
    unsupported,           ///< the input is valid but not handled by this operation
    cancelled,             ///< the caller's progress callback returned false; inputs are unchanged
    unknown_format,        ///< a file name's extension names no format this reader or writer knows
};

/// The error half of a result: a code, a one-line message that names the element, and the
/// element index (or -1).
struct error {
    errc code = errc::invalid_argument;  ///< what kind of failure
    std::string message;                 ///< one line naming what failed and where
    long long element = -1;              ///< index of the offending element, or -1
};

/// Thrown by result<T>::value() on an error, and by the few functions documented to throw.
class hmira_error : public std::runtime_error {
public:
    /// Wraps an error value; what() is its message.
    explicit hmira_error(hmira::error e) : std::runtime_error(e.message), error_(std::move(e)) {}
    /// The error value that was thrown.
    const hmira::error& error() const noexcept { return error_; }

private:
    hmira::error error_;
};

/// Either a T or an error. Test with `if (r)`, read with `*r` or `r.value()` (throws on error).
template <class T>
class [[nodiscard]] result {
public:
    /// A success holding v, or a failure holding e (both implicit, so functions can `return`
    /// either).
    ///@{
    result(T v) : data_(std::in_place_index<0>, std::move(v)) {}             // NOLINT: implicit by design
    result(hmira::error e) : data_(std::in_place_index<1>, std::move(e)) {}  // NOLINT

    ///@}

    /// Whether this holds a value.
    ///@{
    bool has_value() const noexcept { return data_.index() == 0; }
    explicit operator bool() const noexcept { return has_value(); }
    ///@}

    /// The value; throws hmira_error if this holds an error.
    ///@{
    T& value() & {
        check();
        return std::get<0>(data_);
    }
    const T& value() const& {
        check();
        return std::get<0>(data_);
    }
    T&& value() && {
        check();
        return std::get<0>(std::move(data_));
    }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    ///@}

    /// The error. Precondition: !has_value().
    const hmira::error& error() const& { return std::get<1>(data_); }

private:
    void check() const {
        if (data_.index() != 0) throw hmira_error(std::get<1>(data_));
    }
    std::variant<T, hmira::error> data_;
};

/// result<void>: success carries nothing.
template <>
class [[nodiscard]] result<void> {
public:
    /// Success (default), or a failure holding e.
    ///@{
    result() = default;
    result(hmira::error e) : error_(std::move(e)), ok_(false) {}  // NOLINT
    ///@}
    /// Whether the operation succeeded.
    ///@{
    bool has_value() const noexcept { return ok_; }
    explicit operator bool() const noexcept { return ok_; }
    ///@}
    /// Throws hmira_error if the operation failed.
    void value() const {
        if (!ok_) throw hmira_error(error_);
    }
    /// The error. Precondition: !has_value().
    const hmira::error& error() const& { return error_; }

private:
    hmira::error error_;
    bool ok_ = true;
};

/// Shorthand to build an error value: `return fail(errc::topology, "killEV: vertex 3 has degree 2", 3);`
inline hmira::error fail(errc code, std::string message, long long element = -1) {
    return hmira::error{code, std::move(message), element};
}

}  // namespace hmira
