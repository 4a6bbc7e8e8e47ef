// tests/algorithms/delaunay/exact_reference.hpp
// An independent exact reference for the predicates: every double is an integer times a power
// of two, so scaling all inputs by a common power turns them into integers, and the
// determinants are evaluated in a small arbitrary-precision integer type written here.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <vector>

namespace hmira_test {

/// Signed arbitrary-precision integer, base 2^32, magnitude + sign. Just add, sub, mul, sign.
class bigint {
public:
    bigint() = default;
    explicit bigint(std::int64_t v) {
        neg_ = v < 0;
        std::uint64_t m = v < 0 ? std::uint64_t(0) - std::uint64_t(v) : std::uint64_t(v);
        while (m) {
            mag_.push_back(std::uint32_t(m));
            m >>= 32;
        }
    }
    /// v * 2^shift for a non-negative shift.
    static bigint shifted(std::int64_t v, int shift) {
        bigint r(v);
        const int words = shift / 32, bits = shift % 32;
        std::vector<std::uint32_t> m(words, 0);
        std::uint32_t carry = 0;
        for (std::uint32_t w : r.mag_) {
            m.push_back(bits ? (w << bits) | carry : w);
            carry = bits ? (w >> (32 - bits)) : 0;
        }
        if (carry) m.push_back(carry);
        r.mag_ = std::move(m);
        r.trim();
        return r;
    }
    int sign() const { return mag_.empty() ? 0 : (neg_ ? -1 : 1); }

    friend bigint operator-(bigint a) {
        if (!a.mag_.empty()) a.neg_ = !a.neg_;
        return a;
    }
    friend bigint operator+(const bigint& a, const bigint& b) {
        if (a.neg_ == b.neg_) {
            bigint r;
            r.neg_ = a.neg_;
            r.mag_ = add_mag(a.mag_, b.mag_);
            r.trim();
            return r;
        }
        const int c = cmp_mag(a.mag_, b.mag_);
        if (c == 0) return bigint();
        bigint r;
        if (c > 0) {
            r.neg_ = a.neg_;
            r.mag_ = sub_mag(a.mag_, b.mag_);
        } else {
            r.neg_ = b.neg_;
            r.mag_ = sub_mag(b.mag_, a.mag_);
        }
        r.trim();
        return r;
    }
    friend bigint operator-(const bigint& a, const bigint& b) { return a + (-b); }
    friend bigint operator*(const bigint& a, const bigint& b) {
        bigint r;
        if (a.mag_.empty() || b.mag_.empty()) return r;
        r.mag_.assign(a.mag_.size() + b.mag_.size(), 0);
        for (std::size_t i = 0; i < a.mag_.size(); ++i) {
            std::uint64_t carry = 0;
            for (std::size_t j = 0; j < b.mag_.size(); ++j) {
                const std::uint64_t cur = std::uint64_t(a.mag_[i]) * b.mag_[j] + r.mag_[i + j] + carry;
                r.mag_[i + j] = std::uint32_t(cur);
                carry = cur >> 32;
            }
            std::size_t k = i + b.mag_.size();
            while (carry) {
                const std::uint64_t cur = std::uint64_t(r.mag_[k]) + carry;
                r.mag_[k++] = std::uint32_t(cur);
                carry = cur >> 32;
            }
        }
        r.neg_ = a.neg_ != b.neg_;
        r.trim();
        return r;
    }

private:
    std::vector<std::uint32_t> mag_;  // little-endian words
    bool neg_ = false;

    void trim() {
        while (!mag_.empty() && mag_.back() == 0) mag_.pop_back();
        if (mag_.empty()) neg_ = false;
    }
    static int cmp_mag(const std::vector<std::uint32_t>& a, const std::vector<std::uint32_t>& b) {
        if (a.size() != b.size()) return a.size() < b.size() ? -1 : 1;
        for (std::size_t i = a.size(); i-- > 0;)
            if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
        return 0;
    }
    static std::vector<std::uint32_t> add_mag(const std::vector<std::uint32_t>& a,
                                              const std::vector<std::uint32_t>& b) {
        std::vector<std::uint32_t> r(std::max(a.size(), b.size()) + 1, 0);
        std::uint64_t carry = 0;
        for (std::size_t i = 0; i < r.size(); ++i) {
            const std::uint64_t cur = carry + (i < a.size() ? a[i] : 0) + (i < b.size() ? b[i] : 0);
            r[i] = std::uint32_t(cur);
            carry = cur >> 32;
        }
        return r;
    }
    static std::vector<std::uint32_t> sub_mag(const std::vector<std::uint32_t>& a,
                                              const std::vector<std::uint32_t>& b) {
        std::vector<std::uint32_t> r(a.size(), 0);
        std::int64_t borrow = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            std::int64_t cur = std::int64_t(a[i]) - (i < b.size() ? b[i] : 0) - borrow;
            borrow = cur < 0 ? 1 : 0;
            if (cur < 0) cur += std::int64_t(1) << 32;
            r[i] = std::uint32_t(cur);
        }
        return r;
    }
};

/// Converts a set of doubles to bigints sharing one power-of-two scale (exactly).
inline std::vector<bigint> exact_integers(std::initializer_list<double> values) {
    int low = 1 << 20;
    for (double v : values) {
        if (v == 0) continue;
        int e;
        std::frexp(v, &e);
        low = std::min(low, e - 53);
    }
    std::vector<bigint> out;
    for (double v : values) {
        if (v == 0) {
            out.emplace_back();
            continue;
        }
        int e;
        const double f = std::frexp(v, &e);
        const auto mant = static_cast<std::int64_t>(std::ldexp(f, 53));  // exact: 53-bit integer
        out.push_back(bigint::shifted(mant, e - 53 - low));
    }
    return out;
}

/// Exact sign of orient2d(a, b, c).
inline int exact_orient(double ax, double ay, double bx, double by, double cx, double cy) {
    const auto v = exact_integers({ax, ay, bx, by, cx, cy});
    return ((v[0] - v[4]) * (v[3] - v[5]) - (v[1] - v[5]) * (v[2] - v[4])).sign();
}

/// Exact sign of incircle(a, b, c, d).
inline int exact_incircle(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy) {
    const auto v = exact_integers({ax, ay, bx, by, cx, cy, dx, dy});
    const bigint adx = v[0] - v[6], ady = v[1] - v[7];
    const bigint bdx = v[2] - v[6], bdy = v[3] - v[7];
    const bigint cdx = v[4] - v[6], cdy = v[5] - v[7];
    const bigint al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
    return (al * (bdx * cdy - cdx * bdy) + bl * (cdx * ady - adx * cdy) + cl * (adx * bdy - bdx * ady)).sign();
}

}  // namespace hmira_test
