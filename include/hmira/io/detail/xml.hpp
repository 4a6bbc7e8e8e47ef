// hmira/io/detail/xml.hpp
// A small pull parser for the XML that VTK's .vtp and 3MF's model part use: start tags with
// their attributes, end tags, text. Bounded by construction: no DTD (a DOCTYPE is refused, so
// there are no entity expansions), nesting capped, attributes viewed in place, nothing copied.
// Why not libexpat: a .vtp file's appended section is raw binary after "<AppendedData ...>_",
// which is not XML, so an XML library must be stopped at that tag and handed only the prefix;
// and both formats need only flat scans of tags and numeric attributes, which expat's callback
// API turns into a state machine around callbacks for no gain in safety over this bounded scan.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "../../core/result.hpp"
#include "json.hpp"  // printable

namespace hmira::io::detail {

/// One attribute of a start tag, its value as written (entities not decoded).
struct xml_attribute {
    std::string_view name, value;
};

/// What xml_reader::next found.
enum class xml_event { start, end, text, done };

/// Pull parser over a complete document held in memory. After `start`, `name` and
/// `attributes` describe the tag and `self_closing` says whether an `end` follows at once (it
/// is reported as its own event). After `text`, `text` holds the raw characters between tags.
class xml_reader {
public:
    xml_reader(std::string_view data, std::string name, std::size_t max_depth = 256)
        : data_(data), name_(std::move(name)), max_depth_(max_depth) {}

    std::string_view name;                  ///< tag name, namespace prefix removed
    std::string_view text;                  ///< raw text of a text event
    std::vector<xml_attribute> attributes;  ///< of the last start tag
    bool self_closing = false;              ///< the last start tag ended with "/>"
    std::size_t depth() const { return stack_.size(); }
    std::size_t offset() const { return pos_; }  ///< byte offset just past the last event

    /// The attribute's raw value, or null.
    const std::string_view* find(std::string_view key) const {
        for (const auto& a : attributes)
            if (a.name == key) return &a.value;
        return nullptr;
    }

    /// An error naming the document and the byte offset.
    hmira::error bad(const std::string& what, std::size_t at) const {
        return fail(errc::parse_error, name_ + ": byte offset " + std::to_string(at) + ": " + what,
                    static_cast<long long>(at));
    }
    hmira::error bad(const std::string& what) const { return bad(what, pos_); }

    result<xml_event> next() {
        if (pending_end_) {
            pending_end_ = false;
            stack_.pop_back();
            return xml_event::end;
        }
        for (;;) {
            if (pos_ >= data_.size()) {
                if (!stack_.empty())
                    return bad("the document ends inside <" + printable(std::string(stack_.back().substr(0, 64))) +
                               ">");
                return xml_event::done;
            }
            if (data_[pos_] != '<') {
                const std::size_t lt = data_.find('<', pos_);
                text = data_.substr(pos_, lt == std::string_view::npos ? std::string_view::npos : lt - pos_);
                pos_ = lt == std::string_view::npos ? data_.size() : lt;
                if (stack_.empty()) {
                    for (char c : text)
                        if (!is_space(c)) return bad("text outside the root element");
                    continue;
                }
                return xml_event::text;
            }
            const std::string_view rest = data_.substr(pos_);
            if (rest.starts_with("<?")) {
                if (!skip_past("?>")) return bad("unterminated processing instruction");
                continue;
            }
            if (rest.starts_with("<!--")) {
                if (!skip_past("-->")) return bad("unterminated comment");
                continue;
            }
            if (rest.starts_with("<![CDATA[")) {
                const std::size_t begin = pos_ + 9;
                if (!skip_past("]]>")) return bad("unterminated CDATA section");
                text = data_.substr(begin, pos_ - 3 - begin);
                if (stack_.empty()) return bad("CDATA outside the root element");
                return xml_event::text;
            }
            if (rest.starts_with("<!")) return bad("a DOCTYPE or other declaration (not read: no DTDs)");
            if (rest.starts_with("</")) return end_tag();
            return start_tag();
        }
    }

    /// Skips the content of the element just started, up to and including its end tag.
    result<void> skip_element() {
        const std::size_t target = stack_.size() - 1;
        for (;;) {
            auto e = next();
            if (!e) return e.error();
            if (*e == xml_event::done) return bad("the document ends inside an element");
            if (*e == xml_event::end && stack_.size() == target) return {};
        }
    }

    static bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

private:
    static bool is_name_char(char c) {
        return c != '>' && c != '/' && c != '=' && !is_space(c) && c != '<' && c != '"' && c != '\'';
    }
    bool skip_past(std::string_view end) {
        const std::size_t at = data_.find(end, pos_);
        if (at == std::string_view::npos) return false;
        pos_ = at + end.size();
        return true;
    }
    static std::string_view local(std::string_view n) {
        const std::size_t colon = n.find(':');
        return colon == std::string_view::npos ? n : n.substr(colon + 1);
    }
    void skip_spaces() {
        while (pos_ < data_.size() && is_space(data_[pos_])) ++pos_;
    }
    std::string_view read_name() {
        const std::size_t begin = pos_;
        while (pos_ < data_.size() && is_name_char(data_[pos_])) ++pos_;
        return data_.substr(begin, pos_ - begin);
    }
    result<xml_event> end_tag() {
        const std::size_t at = pos_;
        pos_ += 2;
        const std::string_view n = read_name();
        skip_spaces();
        if (pos_ >= data_.size() || data_[pos_] != '>') return bad("malformed end tag", at);
        ++pos_;
        if (stack_.empty() || stack_.back() != n)
            return bad("</" + printable(std::string(n.substr(0, 64))) + "> does not close the open element", at);
        stack_.pop_back();
        name = local(n);
        return xml_event::end;
    }
    result<xml_event> start_tag() {
        const std::size_t at = pos_;
        ++pos_;
        const std::string_view n = read_name();
        if (n.empty()) return bad("a '<' that starts no tag", at);
        if (stack_.empty() && seen_root_) return bad("a second root element", at);
        attributes.clear();
        for (;;) {
            skip_spaces();
            if (pos_ >= data_.size()) return bad("the document ends inside a tag", at);
            const char c = data_[pos_];
            if (c == '>' || c == '/') break;
            const std::string_view key = read_name();
            if (key.empty())
                return bad("malformed attribute in <" + printable(std::string(n.substr(0, 64))) + ">", pos_);
            skip_spaces();
            if (pos_ >= data_.size()) return bad("the document ends inside a tag", at);
            if (data_[pos_] != '=') return bad("attribute without '='", pos_);
            ++pos_;
            skip_spaces();
            if (pos_ >= data_.size() || (data_[pos_] != '"' && data_[pos_] != '\''))
                return bad("attribute value without quotes", pos_);
            const char quote = data_[pos_++];
            const std::size_t close = data_.find(quote, pos_);
            if (close == std::string_view::npos) return bad("the document ends inside an attribute value", pos_);
            attributes.push_back({local(key), data_.substr(pos_, close - pos_)});
            pos_ = close + 1;
        }
        self_closing = data_[pos_] == '/';
        if (self_closing) {
            ++pos_;
            if (pos_ >= data_.size() || data_[pos_] != '>') return bad("malformed empty-element tag", at);
        }
        ++pos_;
        if (stack_.size() >= max_depth_) return bad("elements nested deeper than " + std::to_string(max_depth_), at);
        stack_.push_back(n);
        seen_root_ = true;
        pending_end_ = self_closing;
        name = local(n);
        return xml_event::start;
    }

    std::string_view data_;
    std::string name_;
    std::size_t max_depth_;
    std::size_t pos_ = 0;
    std::vector<std::string_view> stack_;
    bool pending_end_ = false, seen_root_ = false;
};

/// Text with the five predefined entities and numeric character references decoded (others
/// are kept as written); for names and paths, never for bulk numbers.
inline std::string xml_decode(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (s[i] != '&') {
            out += s[i];
            continue;
        }
        const std::size_t semi = s.find(';', i);
        if (semi == std::string_view::npos || semi - i > 10) {
            out += s[i];
            continue;
        }
        const std::string_view e = s.substr(i + 1, semi - i - 1);
        char c = 0;
        if (e == "lt")
            c = '<';
        else if (e == "gt")
            c = '>';
        else if (e == "amp")
            c = '&';
        else if (e == "quot")
            c = '"';
        else if (e == "apos")
            c = '\'';
        else if (e.size() > 1 && e[0] == '#') {
            unsigned v = 0;
            const bool hex = e[1] == 'x';
            for (char d : e.substr(hex ? 2 : 1)) {
                const int digit = d >= '0' && d <= '9'          ? d - '0'
                                  : hex && d >= 'a' && d <= 'f' ? d - 'a' + 10
                                  : hex && d >= 'A' && d <= 'F' ? d - 'A' + 10
                                                                : -1;
                if (digit < 0 || v > 0x10ffff) {
                    v = 0x110000;
                    break;
                }
                v = v * (hex ? 16 : 10) + static_cast<unsigned>(digit);
            }
            if (v < 0x80 && v > 0) c = static_cast<char>(v);
        }
        if (c == 0) {
            out += s[i];
            continue;
        }
        out += c;
        i = semi;
    }
    return out;
}

}  // namespace hmira::io::detail
