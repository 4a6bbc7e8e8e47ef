// docs/concepts.md cannot drift from the code: every concept of concepts.hpp has a section
// there naming each traits operation, type and constant it asks for and each concept it
// refines; the page lists no concept that no longer exists; and each algorithm concept it
// lists is declared in the header it names.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace {

const std::filesystem::path source_dir = HMIRA_SOURCE_DIR;

std::string read_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    EXPECT_TRUE(in) << "cannot read " << p;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct concept_decl {
    std::string body;               // from `concept NAME` to the next declaration
    std::set<std::string> asks;     // T::op(...), typename T::type;, requires T::constant;
    std::set<std::string> refines;  // other concepts of the same file used in the body
};

// The concepts of concepts.hpp with what each asks for, read from the source text.
std::map<std::string, concept_decl> parse_concepts(const std::string& text) {
    std::map<std::string, concept_decl> out;
    const std::regex decl(R"(concept\s+([A-Za-z_]\w*)\s*=)");
    std::vector<std::pair<std::string, std::size_t>> starts;
    for (std::sregex_iterator it(text.begin(), text.end(), decl), end; it != end; ++it)
        starts.emplace_back((*it)[1], static_cast<std::size_t>(it->position(0)));
    for (const auto& [name, from] : starts) {
        // The definition ends at the first ';' outside parentheses and braces.
        std::size_t to = from;
        for (int depth = 0; to < text.size(); ++to) {
            const char ch = text[to];
            if (ch == '(' || ch == '{')
                ++depth;
            else if (ch == ')' || ch == '}')
                --depth;
            else if (ch == ';' && depth == 0)
                break;
        }
        out[name].body = text.substr(from, to - from);
    }
    const std::regex op(R"(T::(\w+)\s*\()"), type(R"(typename\s+T::(\w+)\s*;)"), constant(R"(requires\s+T::(\w+)\s*;)");
    for (auto& [name, c] : out) {
        for (const auto* re : {&op, &type, &constant})
            for (std::sregex_iterator it(c.body.begin(), c.body.end(), *re), end; it != end; ++it)
                c.asks.insert("T::" + (*it)[1].str());
        for (const auto& [other, unused] : out) {
            if (other == name || other == "range_of_handles") continue;  // a helper, not a capability
            if (std::regex_search(c.body, std::regex("\\b" + other + "\\s*<"))) c.refines.insert(other);
        }
    }
    return out;
}

// The sections of concepts.md: "### `name`" up to the next heading.
std::map<std::string, std::string> doc_sections(const std::string& doc) {
    std::map<std::string, std::string> out;
    const std::regex heading(R"(^#{3} `(\w+)`\s*$)", std::regex::multiline);
    std::vector<std::pair<std::string, std::size_t>> starts;
    for (std::sregex_iterator it(doc.begin(), doc.end(), heading), end; it != end; ++it)
        starts.emplace_back((*it)[1], static_cast<std::size_t>(it->position(0)));
    for (std::size_t i = 0; i < starts.size(); ++i) {
        const auto from = starts[i].second;
        auto to = doc.find("\n#", from + 1);
        out[starts[i].first] = doc.substr(from, to == std::string::npos ? std::string::npos : to - from);
    }
    return out;
}

const std::string concepts_hpp = read_file(source_dir / "include" / "hmira" / "concepts.hpp");
const std::string concepts_md = read_file(source_dir / "docs" / "concepts.md");

TEST(concepts_doc, the_parser_finds_the_concepts_and_their_operations) {
    // Guards the test itself: if the parser found nothing, every check below would pass.
    const auto c = parse_concepts(concepts_hpp);
    ASSERT_GE(c.size(), 20u);
    ASSERT_TRUE(c.count("vertex_adjacency_mesh"));
    EXPECT_TRUE(c.at("vertex_adjacency_mesh").asks.count("T::adjacent_vertices"));
    EXPECT_TRUE(c.at("vertex_adjacency_mesh").refines.count("vertex_list_mesh"));
    EXPECT_TRUE(c.at("halfedge_navigable_mesh").asks.count("T::halfedge_handle"));
    EXPECT_TRUE(c.at("polygon_mesh_builder").asks.count("T::triangles_only"));
}

TEST(concepts_doc, every_concept_of_concepts_hpp_has_a_section_naming_what_it_asks_for) {
    const auto sections = doc_sections(concepts_md);
    for (const auto& [name, c] : parse_concepts(concepts_hpp)) {
        ASSERT_TRUE(sections.count(name)) << "docs/concepts.md has no section \"### `" << name << "`\"";
        const auto& text = sections.at(name);
        for (const auto& op : c.asks)
            EXPECT_NE(text.find(op), std::string::npos) << "docs/concepts.md, " << name << ": does not mention " << op;
        for (const auto& base : c.refines)
            EXPECT_NE(text.find("`" + base + "`"), std::string::npos)
                << "docs/concepts.md, " << name << ": does not say it refines " << base;
    }
}

TEST(concepts_doc, the_page_lists_no_concept_that_concepts_hpp_lacks) {
    const auto declared = parse_concepts(concepts_hpp);
    for (const auto& [name, text] : doc_sections(concepts_md))
        EXPECT_TRUE(declared.count(name))
            << "docs/concepts.md describes `" << name << "`, which concepts.hpp no longer declares";
}

TEST(concepts_doc, each_algorithm_concept_listed_is_declared_in_the_header_named) {
    const std::regex row(R"(^\| `(\w+)` \| `([\w/.]+\.hpp)` \|)", std::regex::multiline);
    int rows = 0;
    for (std::sregex_iterator it(concepts_md.begin(), concepts_md.end(), row), end; it != end; ++it, ++rows) {
        const auto header = source_dir / "include" / "hmira" / (*it)[2].str();
        ASSERT_TRUE(std::filesystem::exists(header)) << header;
        EXPECT_TRUE(std::regex_search(read_file(header), std::regex("concept\\s+" + (*it)[1].str() + "\\s*=")))
            << (*it)[1] << " is not declared in " << header;
    }
    EXPECT_GE(rows, 5);
}

}  // namespace
