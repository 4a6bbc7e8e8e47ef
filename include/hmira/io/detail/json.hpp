// hmira/io/detail/json.hpp
// A small JSON reader and writer helpers for the glTF reader and writer: the whole document into
// a tree, bounded by the input (every value costs at least one input byte, nesting at most
// max_json_depth), errors naming the byte offset. Standard library only.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../../core/result.hpp"

namespace hmira::io::detail {

/// Deepest nesting of arrays and objects accepted (a glTF document needs fewer than ten).
inline constexpr int max_json_depth = 64;

/// A JSON value. An array's elements are `items`; an object's member values are `items` too,
/// named by `keys` (same order, the document's); find() is linear, which suits glTF's small
/// objects. (No vector of pairs: a pair holding the still incomplete json_value is ill-formed.)
struct json_value {
    enum class kind : std::uint8_t { null, boolean, number, string, array, object };
    kind type = kind::null;
    bool boolean = false;
    double number = 0;
    std::string text;
    std::vector<json_value> items;
    std::vector<std::string> keys;

    /// The member named `key` of an object, or null (also for a value that is no object).
    const json_value* find(std::string_view key) const {
        if (type != kind::object) return nullptr;
        for (std::size_t i = 0; i < keys.size() && i < items.size(); ++i)
            if (keys[i] == key) return &items[i];
        return nullptr;
    }
    bool is_number() const { return type == kind::number; }
    bool is_string() const { return type == kind::string; }
    bool is_array() const { return type == kind::array; }
    bool is_object() const { return type == kind::object; }
};

/// Text from the file as it may appear in a one-line message: printable ASCII as is, anything
/// else as \xNN, at most 40 characters (then "...").
inline std::string printable(std::string_view s) {
    std::string out;
    for (std::size_t i = 0; i < s.size() && i < 40; ++i) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            static constexpr char hex[] = "0123456789abcdef";
            out += "\\x";
            out += hex[c >> 4];
            out += hex[c & 15];
        }
    }
    if (s.size() > 40) out += "...";
    return out;
}

/// Parses a whole JSON document (trailing whitespace allowed, nothing else after it).
/// Complexity O(bytes). Errors (errc::parse_error): "<name>: byte offset N: <what>".
class json_reader {
public:
    json_reader(std::string_view text, std::string name) : s_(text), name_(std::move(name)) {}

    result<json_value> parse() {
        json_value v;
        if (auto ok = value(v, 0); !ok) return ok.error();
        skip_space();
        if (at_ < s_.size()) return error("unexpected text after the JSON document");
        return v;
    }

private:
    std::string_view s_;
    std::string name_;
    std::size_t at_ = 0;

    hmira::error error(const std::string& what) const {
        return fail(errc::parse_error, name_ + ": byte offset " + std::to_string(at_) + ": " + what,
                    static_cast<long long>(at_));
    }
    void skip_space() {
        while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\t' || s_[at_] == '\n' || s_[at_] == '\r')) ++at_;
    }
    bool literal(std::string_view word) {
        if (s_.substr(at_, word.size()) != word) return false;
        at_ += word.size();
        return true;
    }

    result<void> value(json_value& out, int depth) {
        skip_space();
        if (at_ >= s_.size()) return error("the JSON document ends where a value should be");
        const char c = s_[at_];
        if (c == '{' || c == '[') {
            if (depth >= max_json_depth)
                return error("JSON nested deeper than " + std::to_string(max_json_depth) + " levels");
            return c == '{' ? object(out, depth + 1) : array(out, depth + 1);
        }
        if (c == '"') {
            out.type = json_value::kind::string;
            return string(out.text);
        }
        if (literal("true") || literal("false")) {
            out.type = json_value::kind::boolean;
            out.boolean = s_[at_ - 1] == 'e' && s_[at_ - 2] == 'u';
            return {};
        }
        if (literal("null")) return {};
        return number(out);
    }

    result<void> number(json_value& out) {
        const std::size_t start = at_;
        while (at_ < s_.size() && (std::string_view("+-0123456789.eE").find(s_[at_]) != std::string_view::npos)) ++at_;
        if (start == at_) {
            at_ = start;
            return error("unexpected character '" + printable(s_.substr(start, 1)) + "'");
        }
        const char* first = s_.data() + start;
        const char* last = s_.data() + at_;
        auto [end, ec] = std::from_chars(first, last, out.number);
        if (ec != std::errc() || end != last) {
            at_ = start;
            return error("malformed number '" + std::string(first, last) + "'");
        }
        out.type = json_value::kind::number;
        return {};
    }

    static void append_utf8(std::string& out, std::uint32_t cp) {
        if (cp < 0x80) {
            out += static_cast<char>(cp);
        } else if (cp < 0x800) {
            out += static_cast<char>(0xc0 | (cp >> 6));
            out += static_cast<char>(0x80 | (cp & 0x3f));
        } else if (cp < 0x10000) {
            out += static_cast<char>(0xe0 | (cp >> 12));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
            out += static_cast<char>(0x80 | (cp & 0x3f));
        } else {
            out += static_cast<char>(0xf0 | (cp >> 18));
            out += static_cast<char>(0x80 | ((cp >> 12) & 0x3f));
            out += static_cast<char>(0x80 | ((cp >> 6) & 0x3f));
            out += static_cast<char>(0x80 | (cp & 0x3f));
        }
    }
    result<std::uint32_t> hex4() {
        if (s_.size() - at_ < 4) return error("truncated \\u escape");
        std::uint32_t v = 0;
        auto [end, ec] = std::from_chars(s_.data() + at_, s_.data() + at_ + 4, v, 16);
        if (ec != std::errc() || end != s_.data() + at_ + 4) return error("malformed \\u escape");
        at_ += 4;
        return v;
    }

    result<void> string(std::string& out) {
        ++at_;  // the opening quote
        while (true) {
            if (at_ >= s_.size()) return error("unterminated string");
            const char c = s_[at_++];
            if (c == '"') return {};
            if (static_cast<unsigned char>(c) < 0x20) {
                --at_;
                return error("control character in a string");
            }
            if (c != '\\') {
                out += c;
                continue;
            }
            if (at_ >= s_.size()) return error("unterminated string");
            const char e = s_[at_++];
            switch (e) {
                case '"': out += '"'; break;
                case '\\': out += '\\'; break;
                case '/': out += '/'; break;
                case 'b': out += '\b'; break;
                case 'f': out += '\f'; break;
                case 'n': out += '\n'; break;
                case 'r': out += '\r'; break;
                case 't': out += '\t'; break;
                case 'u': {
                    auto cp = hex4();
                    if (!cp) return cp.error();
                    std::uint32_t code = *cp;
                    if (code >= 0xd800 && code < 0xdc00 && literal("\\u")) {
                        auto low = hex4();
                        if (!low) return low.error();
                        if (*low >= 0xdc00 && *low < 0xe000) code = 0x10000 + ((code - 0xd800) << 10) + (*low - 0xdc00);
                    }
                    append_utf8(out, code);
                    break;
                }
                default: --at_; return error("unknown escape '\\" + printable(std::string_view(&e, 1)) + "'");
            }
        }
    }

    result<void> array(json_value& out, int depth) {
        out.type = json_value::kind::array;
        ++at_;
        skip_space();
        if (at_ < s_.size() && s_[at_] == ']') return ++at_, result<void>{};
        while (true) {
            out.items.emplace_back();
            if (auto ok = value(out.items.back(), depth); !ok) return ok;
            skip_space();
            if (at_ >= s_.size()) return error("unterminated array");
            if (s_[at_] == ']') return ++at_, result<void>{};
            if (s_[at_] != ',') return error("expected ',' or ']' in an array");
            ++at_;
        }
    }

    result<void> object(json_value& out, int depth) {
        out.type = json_value::kind::object;
        ++at_;
        skip_space();
        if (at_ < s_.size() && s_[at_] == '}') return ++at_, result<void>{};
        while (true) {
            skip_space();
            if (at_ >= s_.size() || s_[at_] != '"') return error("expected a member name in quotes");
            out.keys.emplace_back();
            if (auto ok = string(out.keys.back()); !ok) return ok;
            skip_space();
            if (at_ >= s_.size() || s_[at_] != ':') return error("expected ':' after a member name");
            ++at_;
            out.items.emplace_back();
            if (auto ok = value(out.items.back(), depth); !ok) return ok;
            skip_space();
            if (at_ >= s_.size()) return error("unterminated object");
            if (s_[at_] == '}') return ++at_, result<void>{};
            if (s_[at_] != ',') return error("expected ',' or '}' in an object");
            ++at_;
        }
    }
};

}  // namespace hmira::io::detail
