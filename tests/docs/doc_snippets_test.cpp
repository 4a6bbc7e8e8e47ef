// The code quoted in the guides is the code that CI builds: a block marked
// `<!-- snippet: FILE#REGION -->` must equal the lines between the two `// [REGION]` markers
// of FILE (the whole file without #REGION), and a block marked `<!-- excerpt: FILE -->` must
// consist of lines of FILE, in order (a line `// ...` stands for lines left out).
#include <gtest/gtest.h>

#include <algorithm>

#include "doc_support.hpp"

namespace {

using namespace hmira_doc;

const std::vector<std::string> guides = {"docs/own-mesh.md", "docs/new-algorithm.md"};

std::vector<std::string> region(const std::filesystem::path& file, const std::string& name) {
    const auto lines = lines_of(read_file(file));
    if (name.empty()) return lines;
    std::vector<std::string> out;
    const std::string marker = "// [" + name + "]";
    bool inside = false;
    for (const auto& l : lines) {
        if (trim(l) == marker) {
            if (inside) return out;
            inside = true;
        } else if (inside) {
            out.push_back(l);
        }
    }
    ADD_FAILURE() << file << ": no region [" << name << "] closed by a second marker";
    return {};
}

TEST(doc_snippets, every_quoted_snippet_equals_its_source_region) {
    int checked = 0;
    for (const auto& guide : guides)
        for (const auto& b : marked_blocks(source_dir / guide)) {
            if (b.kind != "snippet") continue;
            const auto hash = b.argument.find('#');
            const auto file = b.argument.substr(0, hash);
            const auto name = hash == std::string::npos ? std::string() : b.argument.substr(hash + 1);
            ASSERT_TRUE(std::filesystem::exists(source_dir / file)) << guide << ':' << b.line << ": " << file;
            EXPECT_EQ(b.code, region(source_dir / file, name))
                << guide << ':' << b.line << " quotes " << b.argument << " differently from the source; copy it again";
            ++checked;
        }
    EXPECT_GE(checked, 4) << "the guides quote their examples through snippet markers";
}

TEST(doc_snippets, every_excerpt_is_made_of_source_lines_in_order) {
    int checked = 0;
    for (const auto& guide : guides)
        for (const auto& b : marked_blocks(source_dir / guide)) {
            if (b.kind != "excerpt") continue;
            ASSERT_TRUE(std::filesystem::exists(source_dir / b.argument))
                << guide << ':' << b.line << ": " << b.argument;
            const auto source = lines_of(read_file(source_dir / b.argument));
            std::size_t at = 0;
            for (const auto& l : b.code) {
                if (trim(l) == "// ...") continue;
                const auto it = std::find(source.begin() + static_cast<std::ptrdiff_t>(at), source.end(), l);
                ASSERT_NE(it, source.end()) << guide << ':' << b.line << ": this line is not in " << b.argument
                                            << " (after the previous one):\n"
                                            << l;
                at = static_cast<std::size_t>(it - source.begin()) + 1;
            }
            ++checked;
        }
    EXPECT_GE(checked, 2);
}

}  // namespace
