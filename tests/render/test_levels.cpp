// Which copy of the tracer runs (render/levels.h): the choice by hand for
// CPUs and binaries of each kind, and the command line's answer to a
// FIRSTHIT_ISA it cannot honour.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "cli/run_command.h"
#include "render/levels.h"

namespace fh {
namespace {

// The message choose_level refuses with, or "" when it accepts.
std::string refusal(const std::string& requested, int cpu, const std::vector<int>& compiled) {
    try {
        choose_level(requested, cpu, compiled);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

TEST(Levels, TheWidestTheCpuRunsAmongThoseHeld) {
    const std::vector<int> all = {2, 3, 4};
    EXPECT_EQ(choose_level("", 4, all), 4);
    EXPECT_EQ(choose_level("", 3, all), 3);
    EXPECT_EQ(choose_level("", 2, all), 2);
    EXPECT_EQ(choose_level("", 4, {2, 3}), 3);  // a binary without v4, on an AVX-512 CPU
    EXPECT_EQ(choose_level("", 4, {3}), 3);      // built for x86-64-v3 alone
}

TEST(Levels, ForcingALowerLevelByEitherName) {
    const std::vector<int> all = {2, 3, 4};
    EXPECT_EQ(choose_level("v2", 4, all), 2);
    EXPECT_EQ(choose_level("x86-64-v3", 4, all), 3);
    EXPECT_EQ(choose_level("v4", 4, all), 4);
}

TEST(Levels, ALevelTheCpuLacksIsRefused) {
    EXPECT_EQ(refusal("v4", 3, {2, 3, 4}),
              "FIRSTHIT_ISA=v4: this CPU lacks AVX-512 (avx512f, bw, cd, dq, vl); it runs up to v3");
    EXPECT_EQ(refusal("v3", 2, {2, 3, 4}), "FIRSTHIT_ISA=v3: this CPU lacks AVX2, FMA, BMI1 and BMI2; it runs up to v2");
    EXPECT_EQ(refusal("", 1, {2, 3, 4}),
              "this CPU runs none of the x86-64 levels this binary holds (v2, v3, v4); it lacks SSE4.2 and POPCNT");
    EXPECT_EQ(refusal("", 3, {4}),
              "this CPU runs none of the x86-64 levels this binary holds (v4); it lacks AVX-512 (avx512f, bw, cd, dq, vl)");
}

TEST(Levels, ALevelTheBinaryDoesNotHoldOrNoLevelAtAllIsRefused) {
    EXPECT_EQ(refusal("v2", 4, {4}), "FIRSTHIT_ISA=v2: this binary holds v4 only (it was built with FIRSTHIT_ARCH for one CPU)");
    EXPECT_EQ(refusal("v5", 4, {2, 3, 4}), "FIRSTHIT_ISA=v5: not an x86-64 level (v2, v3 or v4)");
    EXPECT_EQ(refusal("avx2", 4, {2, 3, 4}), "FIRSTHIT_ISA=avx2: not an x86-64 level (v2, v3 or v4)");
}

TEST(Levels, TheCommandLineNamesTheLevelInUse) {
    const auto version = test::run_firsthit("--version");
    ASSERT_EQ(version.status, 0) << version.err;
    EXPECT_NE(version.out.find("tracing at " + level_name(level_in_use()) + ": "), std::string::npos) << version.out;
    for (const int level : compiled_levels()) {
        if (level > cpu_level()) continue;
        const std::string name = level_name(level);
        const auto forced = test::run_shell("FIRSTHIT_ISA=v" + std::to_string(level) + " " + FIRSTHIT_BINARY +
                                            " info " + FIRSTHIT_SOURCE_DIR + "/animations/movie1.yaml");
        ASSERT_EQ(forced.status, 0) << forced.err;
        EXPECT_NE(forced.out.find("\ntracer_level: " + name + "\n"), std::string::npos) << forced.out;
    }
}

TEST(Levels, TheCommandLineRefusesWhatItCannotHonourInOneLine) {
    const auto bad = test::run_shell(std::string("FIRSTHIT_ISA=v5 ") + FIRSTHIT_BINARY + " --version");
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(bad.err, "firsthit: error: FIRSTHIT_ISA=v5: not an x86-64 level (v2, v3 or v4)\n");
    // A level this CPU lacks, where there is one (on an AVX-512 machine
    // every level runs: the refusal is checked by hand above).
    for (int level = cpu_level() + 1; level <= 4; ++level) {
        const auto r = test::run_shell("FIRSTHIT_ISA=v" + std::to_string(level) + " " + FIRSTHIT_BINARY +
                                       " render " + FIRSTHIT_SOURCE_DIR + "/animations/movie1.yaml -o /dev/null");
        EXPECT_EQ(r.status, 2);
        EXPECT_NE(r.err.find("this CPU lacks"), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

}  // namespace
}  // namespace fh
