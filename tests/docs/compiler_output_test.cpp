// The compile error that docs/own-mesh.md quotes is the one g++ prints today: each quoted line
// of a block marked `<!-- compiler-output: FILE -->` must occur in the compiler's output for
// FILE, FILE must be rejected, and FILE with -DHMIRA_SNIPPET_OK (the operation supplied) must
// compile, so that the error is due to the missing operation and nothing else.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "doc_support.hpp"

namespace {

using namespace hmira_doc;

struct run_result {
    int status = -1;
    std::string output;
};

run_result compile(const std::filesystem::path& file, const std::string& extra) {
    const std::string cmd = "LC_ALL=C '" HMIRA_CXX "' -std=c++20 -fsyntax-only " + extra + " -I'" +
                            (source_dir / "include").string() + "' '" + file.string() + "' 2>&1";
    run_result r;
    FILE* pipe = popen(cmd.c_str(), "r");
    if (!pipe) return r;
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.output.append(buf, n);
    r.status = pclose(pipe);
    return r;
}

TEST(compiler_output, the_quoted_compile_error_is_what_gxx_prints_for_the_missing_operation) {
    // The guide quotes g++ 12, the project's compiler; another compiler words it differently.
    if (std::string(HMIRA_CXX_ID).rfind("GNU-12.", 0) != 0)
        GTEST_SKIP() << "the quote is g++ 12's; this is " << HMIRA_CXX_ID;
    int checked = 0;
    for (const auto& b : marked_blocks(source_dir / "docs" / "own-mesh.md")) {
        if (b.kind != "compiler-output") continue;
        const auto file = source_dir / b.argument;
        const auto bad = compile(file, "");
        ASSERT_NE(bad.status, 0) << b.argument << " compiled, but the guide says it is rejected";
        for (const auto& quoted : b.code) {
            const auto line = trim(quoted);
            if (line.empty() || line.rfind("...", 0) == 0) continue;
            EXPECT_NE(bad.output.find(line), std::string::npos)
                << "own-mesh.md:" << b.line << " quotes a line g++ no longer prints:\n  " << line << "\ng++ said:\n"
                << bad.output;
        }
        const auto good = compile(file, "-DHMIRA_SNIPPET_OK");
        EXPECT_EQ(good.status, 0) << b.argument << " with the operation supplied still fails:\n" << good.output;
        ++checked;
    }
    EXPECT_GE(checked, 1) << "own-mesh.md quotes at least one compiler error";
}

}  // namespace
