// Frame file names: the default frame_NNNN.png padded to the movie's length,
// and --out patterns, written and read back.
#include <gtest/gtest.h>

#include <filesystem>

#include "pipeline/frame_files.h"

namespace fh {
namespace {

TEST(FrameFiles, DefaultNamesArePaddedToFourDigitsOrMore) {
    EXPECT_EQ(FrameFiles{}.name(0, 300), "frame_0000.png");
    EXPECT_EQ(FrameFiles{}.name(42, 300), "frame_0042.png");
    EXPECT_EQ(FrameFiles{}.name(42, 10001), "frame_00042.png");
    EXPECT_EQ(FrameFiles{}.name(9999, 10000), "frame_9999.png");
}

TEST(FrameFiles, PatternsNameTheFilesAndReadThemBack) {
    const FrameFiles files = parse_frame_files("shots/take1_###.png");
    EXPECT_EQ(files.path(7, 12), std::filesystem::path("shots/take1_007.png"));
    EXPECT_EQ(files.pattern(12), "take1_%03d.png");
    EXPECT_EQ(files.frame_of("take1_0123.png"), 123);
    EXPECT_EQ(files.frame_of("take1_movie.txt"), -1);
    EXPECT_EQ(FrameFiles{}.pattern(20000), "frame_%05d.png");
}

}  // namespace
}  // namespace fh
