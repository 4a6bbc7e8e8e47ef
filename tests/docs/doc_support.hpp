// tests/docs/doc_support.hpp
// Reading the guides: files under the source tree, and the fenced code blocks that follow a
// marker comment such as `<!-- snippet: examples/x/y.hpp#traits -->`.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hmira_doc {

inline const std::filesystem::path source_dir = HMIRA_SOURCE_DIR;

inline std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

inline std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

inline std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

/// A marked code block of a guide: `<!-- KIND: ARGUMENT -->` followed by a fenced block.
struct marked_block {
    std::string doc, kind, argument;
    std::size_t line = 0;           // 1-based line of the marker
    std::vector<std::string> code;  // the block's lines, fences excluded
};

inline std::vector<marked_block> marked_blocks(const std::filesystem::path& doc) {
    std::vector<marked_block> out;
    const auto lines = lines_of(read_file(doc));
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const auto l = trim(lines[i]);
        if (l.rfind("<!-- ", 0) != 0 || l.size() < 9 || l.substr(l.size() - 4) != " -->") continue;
        const auto colon = l.find(": ");
        if (colon == std::string::npos) continue;
        marked_block b{doc.filename().string(),
                       l.substr(5, colon - 5),
                       trim(l.substr(colon + 2, l.size() - 4 - colon - 2)),
                       i + 1,
                       {}};
        std::size_t j = i + 1;
        while (j < lines.size() && trim(lines[j]).rfind("```", 0) != 0) ++j;
        for (++j; j < lines.size() && trim(lines[j]).rfind("```", 0) != 0; ++j) b.code.push_back(lines[j]);
        out.push_back(std::move(b));
    }
    return out;
}

}  // namespace hmira_doc
