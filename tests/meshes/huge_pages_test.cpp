// The huge-page hint (core/huge_pages.hpp): large arrays that are filled next are advised to
// the kernel (their mapping carries the "hg" flag in /proc/self/smaps), small ones are left
// alone, and the hint never changes contents, whatever the pointer and size.
#include <gtest/gtest.h>

#include <hmira/core/huge_pages.hpp>
#include <hmira/core/uninitialized_vector.hpp>
#include <hmira/meshes/detail/trivial_array.hpp>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

bool thp_available() {
#if defined(HMIRA_NO_HUGE_PAGES) || !__has_include(<sys/mman.h>)
    return false;
#else
    std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string mode;
    return static_cast<bool>(std::getline(in, mode));
#endif
}

// The VmFlags of the mapping that holds address p, from /proc/self/smaps ("" if none).
std::string vm_flags_at(const void* p) {
    const auto a = reinterpret_cast<std::uintptr_t>(p);
    std::ifstream in("/proc/self/smaps");
    std::string line;
    bool inside = false;
    while (std::getline(in, line)) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(':') > line.find(' ')) {
            inside = lo <= a && a < hi;
            continue;
        }
        if (inside && line.rfind("VmFlags:", 0) == 0) return line;
    }
    return "";
}

bool advised(const void* p) { return vm_flags_at(p).find(" hg") != std::string::npos; }

constexpr std::size_t mib = std::size_t{1} << 20;

}  // namespace

TEST(HugePages, TrivialArrayOfManyMegabytesIsAdvisedAndKeepsItsValues) {
    if (!thp_available()) GTEST_SKIP() << "no transparent huge pages here";
    hmira::detail::trivial_array<std::uint64_t> a;
    for (std::uint64_t i = 0; i < 3 * mib; ++i) a.push_back(i * 7 + 1);  // 24 MiB, grown step by step
    ASSERT_EQ(a.size(), 3 * mib);
    // The whole block, ends included: advice on part of a mapping would split it, and then
    // realloc copies the block instead of moving its pages with one mremap.
    EXPECT_TRUE(advised(a.data() + a.size() / 2)) << vm_flags_at(a.data() + a.size() / 2);
    EXPECT_TRUE(advised(a.data())) << vm_flags_at(a.data());
    EXPECT_TRUE(advised(a.data() + a.size() - 1)) << vm_flags_at(a.data() + a.size() - 1);
    for (std::uint64_t i = 0; i < a.size(); i += 4099) ASSERT_EQ(a[i], i * 7 + 1) << i;
    EXPECT_EQ(a[a.size() - 1], (3 * mib - 1) * 7 + 1);
}

TEST(HugePages, UninitializedVectorAndReservedVectorAreAdvised) {
    if (!thp_available()) GTEST_SKIP() << "no transparent huge pages here";
    hmira::uninitialized_vector<double> out(2 * mib);  // 16 MiB
    EXPECT_TRUE(advised(out.data() + out.size() / 2));
    std::vector<std::uint32_t> v;
    hmira::detail::reserve_huge(v, 4 * mib);  // 16 MiB
    ASSERT_GE(v.capacity(), 4 * mib);
    EXPECT_TRUE(advised(v.data() + v.capacity() / 2));
}

TEST(HugePages, SmallBlocksAreLeftAlone) {
    if (!thp_available()) GTEST_SKIP() << "no transparent huge pages here";
    // Under the threshold nothing is advised, even a block that covers a whole huge page: a
    // private mapping of our own so that no other allocation shares its flags.
    const std::size_t bytes = hmira::detail::huge_page_min_bytes - 4096;
    void* block = std::aligned_alloc(hmira::detail::huge_page_bytes, bytes + 4096);
    ASSERT_NE(block, nullptr);
    const bool before = advised(block);
    hmira::detail::advise_huge_pages(block, bytes);
    EXPECT_EQ(advised(block), before);
    std::free(block);
}

TEST(HugePages, HintNeverChangesContentsWhateverThePointerAndSize) {
    // Null, empty, tiny, unaligned and partly touched blocks: no crash, bytes unchanged.
    hmira::detail::advise_huge_pages(nullptr, 0);
    hmira::detail::advise_huge_pages(nullptr, 64 * mib);
    std::vector<unsigned char> bytes(9 * mib + 123);
    for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<unsigned char>(i * 31 + 5);
    hmira::detail::advise_huge_pages(bytes.data() + 1, bytes.size() - 1);
    hmira::detail::advise_huge_pages(bytes.data() + 3, 17);
    for (std::size_t i = 0; i < bytes.size(); ++i) ASSERT_EQ(bytes[i], static_cast<unsigned char>(i * 31 + 5)) << i;
}
