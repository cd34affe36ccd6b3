// The program's malloc on huge pages (cli/huge_page_malloc.cpp), checked in
// a child process -- it changes malloc for the whole process -- through
// /proc/self/smaps: the end of a 4 MiB block (which glibc would otherwise
// map on its own, on small pages) lies in the heap, whose part from its
// first 2 MiB boundary on asks for huge pages over at least 512 MiB.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "cli/huge_page_malloc.h"
#include "sanitizer_build.h"

namespace fh {
namespace huge_page_malloc_test {

bool huge_pages_possible() {
    std::ifstream f("/sys/kernel/mm/transparent_hugepage/enabled");
    std::string s;
    std::getline(f, s);
    return !s.empty() && s.find("[never]") == std::string::npos;
}

// In the child: 0 if the mapping holding the last byte of a fresh 4 MiB
// block is eligible for huge pages and at least 512 MiB long; else what
// failed. (Its first bytes may lie below the heap's first 2 MiB boundary.)
int check_in_child() {
    use_huge_page_malloc();
    constexpr std::size_t kBlock = std::size_t(4) << 20;
    void* volatile block = std::malloc(kBlock);
    const auto at = reinterpret_cast<std::uintptr_t>(block) + kBlock - 1;
    std::ifstream smaps("/proc/self/smaps");
    std::string line;
    bool inside = false;
    std::uintptr_t lo = 0, hi = 0;
    while (std::getline(smaps, line)) {
        unsigned long a = 0, b = 0;
        if (std::sscanf(line.c_str(), "%lx-%lx ", &a, &b) == 2) {
            inside = a <= at && at < b;
            if (inside) lo = a, hi = b;
            continue;
        }
        if (inside && line.rfind("THPeligible:", 0) == 0) {
            if (std::stoi(line.substr(12)) != 1) return 3;
            return hi - lo >= (std::uintptr_t(512) << 20) ? 0 : 4;
        }
    }
    return 5;
}

// The check runs in a fresh copy of this program (forked and started
// again, this test alone): in a process that has run other tests the heap
// may hold free space below the part that asks, where the block would go.
TEST(HugePageMalloc, ABigBlockLiesInAHeapThatAsksForHugePages) {
    if (kMallocSanitized) GTEST_SKIP() << "a sanitizer's malloc replaces glibc's";
    if (!huge_pages_possible()) GTEST_SKIP() << "transparent huge pages are off on this machine";
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        if (!std::freopen("/dev/null", "w", stdout)) _exit(7);
        setenv("FIRSTHIT_HUGE_PAGE_CHILD", "1", 1);
        execl("/proc/self/exe", "firsthit_tests", "--gtest_filter=HugePageMalloc.CheckedInAFreshProcess",
              static_cast<char*>(nullptr));
        _exit(6);  // not started again
    }
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    // 3: not eligible, 4: shorter than the reserve, 5: not found in smaps,
    // 6 and 7: the copy could not start.
    EXPECT_EQ(WEXITSTATUS(status), 0);
}

// The fresh copy's part of the test above; skipped when run on its own.
TEST(HugePageMalloc, CheckedInAFreshProcess) {
    if (!std::getenv("FIRSTHIT_HUGE_PAGE_CHILD")) GTEST_SKIP() << "the copy that ABigBlockLies... starts runs this";
    _exit(check_in_child());
}

}  // namespace huge_page_malloc_test
}  // namespace fh
