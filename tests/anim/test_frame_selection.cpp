// --range, --shard and frame file names.
#include <gtest/gtest.h>

#include <stdexcept>

#include "anim/frame_selection.h"

namespace fh {
namespace {

TEST(FrameSelection, RangeIsHalfOpen) {
    EXPECT_EQ(select_frames(300, FrameRange{10, 13}, std::nullopt), (std::vector<int>{10, 11, 12}));
    EXPECT_EQ(select_frames(3, std::nullopt, std::nullopt), (std::vector<int>{0, 1, 2}));
}

TEST(FrameSelection, ShardsCoverEveryFrameExactlyOnce) {
    for (int shards : {1, 2, 3, 7, 300, 301}) {
        std::vector<int> count(300, 0);
        for (int k = 0; k < shards; ++k)
            for (int i : select_frames(300, std::nullopt, Shard{k, shards})) count[size_t(i)]++;
        for (int c : count) ASSERT_EQ(c, 1) << shards << " shards";
    }
    EXPECT_EQ(select_frames(10, FrameRange{2, 8}, Shard{1, 3}), (std::vector<int>{4, 7}));
}

TEST(FrameSelection, ParsesAndRejects) {
    EXPECT_EQ(parse_range("3:9").begin, 3);
    EXPECT_EQ(parse_range("3:9").end, 9);
    EXPECT_EQ(parse_shard("2/5").index, 2);
    EXPECT_EQ(parse_shard("2/5").count, 5);
    for (const char* bad : {"", "3", "9:3", "3:3", "a:b", "-1:4", "1:2:3"})
        EXPECT_THROW(parse_range(bad), std::invalid_argument) << bad;
    for (const char* bad : {"", "1", "5/5", "1/0", "x/2", "-1/2"})
        EXPECT_THROW(parse_shard(bad), std::invalid_argument) << bad;
    EXPECT_THROW(select_frames(300, FrameRange{0, 301}, std::nullopt), std::invalid_argument);
}

// A-B includes B, as POV-Ray's +SF/+EF and Blender's -s/-e do; A: and A- run
// to the end, whatever the movie's length.
TEST(FrameSelection, InclusiveAndOpenRanges) {
    EXPECT_EQ(parse_range("5-8").begin, 5);
    EXPECT_EQ(parse_range("5-8").end, 9);
    EXPECT_EQ(parse_range("5-5").end, 6);
    EXPECT_EQ(parse_range("5:").end, -1);
    EXPECT_EQ(parse_range("5-").end, -1);
    for (const char* bad : {"8-5", "5--8", "-", ":", "5-x"})
        EXPECT_THROW(parse_range(bad), std::invalid_argument) << bad;
    EXPECT_EQ(select_frames(10, parse_range("7:"), std::nullopt), (std::vector<int>{7, 8, 9}));
    EXPECT_EQ(select_frames(10, parse_range("7-9"), std::nullopt), (std::vector<int>{7, 8, 9}));
    try {
        select_frames(10, parse_range("10:"), std::nullopt);
        FAIL() << "a range starting past the end was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "frame 10 is past the movie's end: its 10 frames are 0 to 9");
    }
}

// Digits only, leading zeros allowed, at most 10^9; what is wrong is said.
TEST(FrameSelection, FrameNumberProblems) {
    long long v = -1;
    EXPECT_EQ(frame_number_problem("0", v), "");
    EXPECT_EQ(v, 0);
    EXPECT_EQ(frame_number_problem("000000000000042", v), "");
    EXPECT_EQ(v, 42);
    EXPECT_EQ(frame_number_problem("1000000000", v), "");
    EXPECT_EQ(v, 1000000000);
    for (const char* bad : {"", "+5", " 5", "5 ", "-0", "1e3", "0x10"})
        EXPECT_EQ(frame_number_problem(bad, v), "is not a whole number >= 0") << bad;
    for (const char* big : {"1000000001", "9999999999", "99999999999999999999999"})
        EXPECT_EQ(frame_number_problem(big, v), "is more than 1000000000") << big;
    EXPECT_EQ(v, 1000000000);  // untouched by a refusal
}

}  // namespace
}  // namespace fh
