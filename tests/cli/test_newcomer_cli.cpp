// The command line as a newcomer from POV-Ray or Blender drives it: sizes
// overridden on the command line, the image format from the extension, frame
// files named by a pattern, frames picked by number or range, a folder of
// another movie's frames refused, one plain line on success, --stats that
// explains itself. Exit status, message and files written, each time.
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "cli/small_movie.h"
#include "images/png_writer.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

// DIR/tiny.yaml: 64 x 64, 12 frames at 12 fps.
fs::path tiny(const std::string& name) { return small_movie(name, 64, 64, 12, "tiny.yaml"); }

std::string q(const fs::path& p) { return "'" + p.string() + "'"; }

std::pair<int, int> size_of(const fs::path& png) { return png_size(png.string()).value_or(std::pair(0, 0)); }

TEST(NewcomerCli, ResolutionAndScaleOverrideTheFilesSize) {
    const fs::path dir = tiny("override_size");
    const std::string movie = q(dir / "tiny.yaml");
    auto r = run_firsthit("render " + movie + " --resolution 40x30 -o " + q(dir / "a.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(size_of(dir / "a.png"), std::pair(40, 30));
    r = run_firsthit("render " + source_path("animations/scene.yaml") + " --scale 0.05 -o " + q(dir / "b.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(size_of(dir / "b.png"), std::pair(40, 40));  // 800 x 0.05
    r = run_firsthit("bench " + movie + " --runs 1 --resolution 20x10");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("width: 20\nheight: 10\n"), std::string::npos) << r.out;
    // A frame rendered by `frames` at an override is the one `render` gives.
    r = run_firsthit("frames " + movie + " --quiet --frame 5 --resolution 24x16 --out " + q(dir / "f"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_firsthit("render " + movie + " --quiet --frame 5 --resolution 24x16 -o " + q(dir / "r5.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir / "f" / "frame_0005.png"), slurp(dir / "r5.png"));
    EXPECT_EQ(size_of(dir / "r5.png"), std::pair(24, 16));

    const std::vector<std::pair<std::string, std::string>> bad = {
        {"--resolution 160", "--resolution takes WIDTHxHEIGHT, e.g. 160x120, got '160'"},
        {"--resolution 0x10", "--resolution's width must be in [1, 16384], got 0"},
        {"--resolution 10x99999", "--resolution's height must be in [1, 16384], got 99999"},
        {"--scale 0", "--scale must be a number in [1e-06, 16384], got '0'"},
        {"--scale 100", "--scale makes a side of 6400 pixels; at most 16384"},
        {"--scale 0.5 --resolution 10x10", "--resolution and --scale both set the size: give one"},
    };
    for (const auto& [flags, message] : bad) {
        if (flags == "--scale 100") continue;  // 64 x 100 fits: checked below on the 800 scene
        r = run_firsthit("render " + movie + " " + flags + " -o " + q(dir / "bad.png"));
        EXPECT_EQ(r.status, 2) << flags;
        EXPECT_EQ(r.err, "firsthit: error: " + message + "\n") << flags;
    }
    r = run_firsthit("render " + source_path("animations/scene.yaml") + " --scale 100 -o " + q(dir / "bad.png"));
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "firsthit: error: --scale makes a side of 80000 pixels; at most 16384\n");
    EXPECT_FALSE(fs::exists(dir / "bad.png"));
}

TEST(NewcomerCli, TheExtensionPicksTheImageFormat) {
    const fs::path dir = tiny("image_formats");
    const std::string movie = q(dir / "tiny.yaml");
    const std::vector<std::pair<std::string, std::string>> magic = {
        {"x.png", "\x89PNG"}, {"x.JPG", "\xff\xd8\xff"}, {"x.jpeg", "\xff\xd8\xff"}, {"x.bmp", "BM"}};
    for (const auto& [name, head] : magic) {
        const auto r = run_firsthit("render " + movie + " --quiet -o " + q(dir / name));
        ASSERT_EQ(r.status, 0) << name << r.err;
        EXPECT_EQ(slurp(dir / name).substr(0, head.size()), head) << name;
    }
    const auto tga = run_firsthit("render " + movie + " --quiet -o " + q(dir / "x.tga"));
    ASSERT_EQ(tga.status, 0) << tga.err;
    EXPECT_EQ(slurp(dir / "x.tga")[2], '\x0a');  // TGA image type 10: run-length true colour
    for (const std::string name : {"x.gif", "x.exr", "noext"}) {
        const auto r = run_firsthit("render " + movie + " -o " + q(dir / name));
        EXPECT_EQ(r.status, 2) << name;
        const std::string why = name == "noext" ? "no extension" : "unknown extension '" + name.substr(1) + "'";
        EXPECT_EQ(r.err, "firsthit: error: cannot write '" + (dir / name).string() + "': " + why +
                             "; the extension picks the format: .png, .jpg or .jpeg, .bmp, .tga ('-': PNG to "
                             "standard output)\n");
        EXPECT_FALSE(fs::exists(dir / name));
    }
    // -o -: the same PNG bytes on standard output, nothing else there.
    const auto out = run_firsthit("render " + movie + " -o -");
    ASSERT_EQ(out.status, 0) << out.err;
    EXPECT_EQ(out.out, slurp(dir / "x.png"));
    EXPECT_EQ(out.err.rfind("wrote PNG to standard output (64x64, 1 frame in ", 0), 0u) << out.err;
    const auto stats = run_firsthit("render " + movie + " -o - --stats");
    EXPECT_EQ(stats.status, 2);
    EXPECT_EQ(stats.err, "firsthit: error: -o - writes the image to standard output: not with --stats\n");
}

TEST(NewcomerCli, RenderSaysWhatItWroteUnlessQuiet) {
    const fs::path dir = tiny("render_says");
    const std::string movie = q(dir / "tiny.yaml");
    auto r = run_firsthit("render " + movie + " -o " + q(dir / "r.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_TRUE(std::regex_match(r.err, std::regex("wrote " + (dir / "r.png").string() +
                                                   " \\(64x64, 1 frame in [0-9]+(\\.[0-9])? (ms|s)\\)\n")))
        << r.err;
    r = run_firsthit("render " + movie + " --quiet -o " + q(dir / "quiet.png"));
    ASSERT_EQ(r.status, 0);
    EXPECT_EQ(r.out + r.err, "");
    EXPECT_TRUE(fs::exists(dir / "quiet.png"));
    r = run_firsthit("frames " + movie + " --out " + q(dir / "f"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(std::regex_match(
        r.err, std::regex("rendered 12 frames in [0-9]+(\\.[0-9])? (ms|s) \\([0-9]+(\\.[0-9])? frames/s\\) into " +
                          (dir / "f").string() + "\n")))
        << r.err;
    r = run_firsthit("frames " + movie + " --quiet --out " + q(dir / "f"));
    EXPECT_EQ(r.out + r.err, "");
}

TEST(NewcomerCli, FramesPicksFramesByNumberOrRange) {
    const fs::path dir = tiny("frames_pick");
    const std::string movie = q(dir / "tiny.yaml");
    auto frames = [&](const std::string& out, const std::string& flags) {
        return run_firsthit("frames " + movie + " --quiet --resolution 8x8 --out " + q(dir / out) + " " + flags);
    };
    ASSERT_EQ(frames("one", "--frame 3").status, 0);
    EXPECT_EQ(frames_in(dir / "one"), std::vector<std::string>{"frame_0003.png"});
    ASSERT_EQ(frames("open", "--range 9:").status, 0);
    EXPECT_EQ(frames_in(dir / "open"), (std::vector<std::string>{"frame_0009.png", "frame_0010.png", "frame_0011.png"}));
    ASSERT_EQ(frames("inclusive", "--range 2-4").status, 0);
    EXPECT_EQ(frames_in(dir / "inclusive"), (std::vector<std::string>{"frame_0002.png", "frame_0003.png", "frame_0004.png"}));
    ASSERT_EQ(frames("slice", "--range 2:4").status, 0);
    EXPECT_EQ(frames_in(dir / "slice"), (std::vector<std::string>{"frame_0002.png", "frame_0003.png"}));
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"--range 5-20", "--range 5-20: frame 20 is past the movie's end: its 12 frames are 0 to 11"},
        {"--range 12:", "--range 12:: frame 12 is past the movie's end: its 12 frames are 0 to 11"},
        {"--range 8-5", "--range 8-5 is empty: A-B needs A <= B"},
        {"--frame 12", "--frame must be in [0, 11], got 12"},
        {"--frame 3 --range 1-2", "--frame N is --range N-N: give one of them"},
    };
    for (const auto& [flags, message] : bad) {
        const auto r = frames("bad", flags);
        EXPECT_EQ(r.status, 2) << flags;
        EXPECT_EQ(r.err, "firsthit: error: " + message + "\n") << flags;
    }
    EXPECT_FALSE(fs::exists(dir / "bad"));
}

TEST(NewcomerCli, FramesOutTakesAPattern) {
    const fs::path dir = tiny("frames_pattern");
    const std::string movie = q(dir / "tiny.yaml");
    auto r = run_firsthit("frames " + movie + " --quiet --range 0-1 --out " + q(dir / "shots/take1_%04d.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_firsthit("frames " + movie + " --quiet --range 0-1 --out " + q(dir / "shots/take2_###.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files_in(dir / "shots"), (std::vector<std::string>{"take1_0000.png", "take1_0001.png", "take1_movie.txt",
                                                                  "take2_000.png", "take2_001.png", "take2_movie.txt"}));
    EXPECT_EQ(slurp(dir / "shots/take2_movie.txt"),
              "# firsthit frames: the movie these frames belong to (scripts/encode.sh reads it)\nmovie: " +
                  fs::absolute(dir / "tiny.yaml").lexically_normal().string() +
                  "\nframes: 12\nfps: 12\nwidth: 64\nheight: 64\npattern: take2_%03d.png\n"
                  "render: camera perspective, 1 sample, depth 5, double\n");
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"a%04d/b.png", "the frame number (%04d or ####) goes in the file name, not the folder"},
        {"a%04d_##.png", "has two frame numbers; give one (%04d or ####)"},
        {"take_%04d.jpg", "frames are PNG files (resume and scripts/encode.sh read them); end the pattern in .png, "
                          "e.g. 'shots/take1_%04d.png'"},
        {"take.png", "names one file, but a movie has many frames: put %04d or #### where the frame number goes, "
                     "e.g. '" + (dir / "take_%04d.png").string() + "'"},
        {"take_%s.png", "'%' stands for the frame number only as %d or %04d"},
    };
    for (const auto& [out, why] : bad) {
        r = run_firsthit("frames " + movie + " --out " + q(dir / out));
        EXPECT_EQ(r.status, 2) << out;
        EXPECT_NE(r.err.find(why), std::string::npos) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
}

TEST(NewcomerCli, FramesRefusesAnotherMoviesFramesUnlessClean) {
    const fs::path dir = tiny("frames_claim");
    const std::string movie = q(dir / "tiny.yaml");
    const fs::path out = dir / "f";
    ASSERT_EQ(run_firsthit("frames " + movie + " --quiet --out " + q(out)).status, 0);
    // The same movie at another size: refused, the old frames untouched.
    auto r = run_firsthit("frames " + movie + " --quiet --resolution 32x32 --out " + q(out));
    EXPECT_EQ(r.status, 2);
    const std::string absolute = fs::absolute(dir / "tiny.yaml").lexically_normal().string();
    const std::string kRender = "camera perspective, 1 sample, depth 5, double";
    EXPECT_EQ(r.err, "firsthit: error: " + (out / "frame_*.png").string() + " holds frames of " + absolute +
                         ": 12 frames at 12 fps, 64x64 (" + kRender + "); this render is " + absolute +
                         ": 12 frames at 12 fps, 32x32 (" + kRender +
                         "). Pass --clean to remove the old frames first, or another --out\n");
    EXPECT_EQ(size_of(out / "frame_0011.png"), std::pair(64, 64));
    // A shorter version of the movie: refused too.
    const fs::path shorter = dir / "shorter.yaml";
    std::ofstream(shorter) << std::regex_replace(slurp(dir / "tiny.yaml"), std::regex("seconds: 1"), "seconds: 0.5");
    r = run_firsthit("frames " + q(shorter) + " --quiet --out " + q(out));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("6 frames at 12 fps, 64x64 (" + kRender + "). Pass --clean"), std::string::npos) << r.err;
    EXPECT_EQ(run_firsthit("frames " + q(shorter) + " --clean --resume --out " + q(out)).err,
              "firsthit: error: --clean removes the frames --resume would keep: give one\n");
    // --clean: the old frames go, the new ones come.
    r = run_firsthit("frames " + q(shorter) + " --clean --out " + q(out));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err.rfind("firsthit: --clean removed 12 old frames in " + out.string() + "\n", 0), 0u) << r.err;
    EXPECT_EQ(frames_in(out).size(), 6u);
    // Without a movie file (an older firsthit, or frames copied by hand),
    // frames past the end are still found.
    fs::remove(out / "frame_movie.txt");
    fs::copy_file(out / "frame_0000.png", out / "frame_0020.png");
    r = run_firsthit("frames " + q(shorter) + " --quiet --out " + q(out));
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("holds frames past this movie's end (frame_0020.png)"), std::string::npos) << r.err;
}

TEST(NewcomerCli, StatsNeverContradictThemselves) {
    const fs::path dir = tiny("stats_plan");
    const std::string scene = source_path("animations/scene.yaml");
    auto r = run_firsthit("render " + scene + " --stats --scale 0.05 -o " + q(dir / "a.png"));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out.find("pruned:"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nskipped: nothing (every effect asked for can change a pixel)\n"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("\nadaptive: off\n"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("refined_pixels"), std::string::npos) << r.out;
    r = run_firsthit("render " + q(dir / "tiny.yaml") + " --stats -o " + q(dir / "b.png"));
    EXPECT_NE(r.out.find("\nskipped: light 'directional': off\n"), std::string::npos) << r.out;
    r = run_firsthit("render " + q(dir / "tiny.yaml") + " --stats --no-prune -o " + q(dir / "c.png"));
    EXPECT_NE(r.out.find("\nskipped: nothing (--no-prune: every effect asked for is simulated)\n"), std::string::npos)
        << r.out;
    // Adaptive: its settings and the pixels it refined.
    r = run_firsthit("render " + scene + " --stats --scale 0.05 --adaptive -o " + q(dir / "d.png"));
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex("\nadaptive: on\nadaptive_threshold: 8\nadaptive_samples: 16\n"
                                                        "refined_pixels: ([0-9]+)\n")))
        << r.out;
    EXPECT_GT(std::stoi(m[1]), 0);
    EXPECT_LT(std::stoi(m[1]), 40 * 40);
    r = run_firsthit("frames " + q(dir / "tiny.yaml") + " --quiet --stats --adaptive --range 0-1 --out " + q(dir / "f"));
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex("\nrefined_pixels: ([0-9]+)\n"))) << r.out;
    EXPECT_GT(std::stoi(m[1]), 0);
}

// Without an output folder, make_movie.sh writes into output/ of the folder
// it is run from, never into the checkout it lives in.
TEST(NewcomerCli, MakeMovieWritesWhereItIsRun) {
    const fs::path dir = tiny("make_movie_here");
    const auto r = run_shell("cd " + q(dir) + " && FIRSTHIT=" + std::string(FIRSTHIT_BINARY) + " " +
                             source_path("scripts/make_movie.sh") + " tiny.yaml --quiet");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(fs::exists(dir / "output/tiny.mp4"));
    EXPECT_EQ(frames_in(dir / "output/tiny").size(), 12u);
    EXPECT_EQ(r.out, "tiny: rendered and encoded into output/tiny.mp4 in " + r.out.substr(r.out.rfind(" in ") + 4));
}

}  // namespace
}  // namespace fh::test
