// scripts/encode.sh as a POV-Ray or Blender user drives it: the format from
// OUT's extension (.mp4, .webm, .gif, .mov; others refused), the fps from
// --movie or the frames' PREFIXmovie.txt (--fps wins, else 30 with a warning), and
// the folder checked against the movie's frame count. Tiny movies (64 x 64,
// one second) made from the report's scene; the videos checked with ffprobe.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "cli/small_movie.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

// Renders the movie's frames (`extra`: e.g. --range A:B) into DIR/f; returns DIR/f.
fs::path render_frames(const fs::path& dir, const std::string& extra = "") {
    const fs::path out = dir / "f";
    const auto r = run_firsthit("frames " + (dir / "tiny.yaml").string() + " --quiet --out " + out.string() + " " + extra);
    EXPECT_EQ(r.status, 0) << r.err;
    return out;
}

CommandResult encode(const std::string& args) { return run_script("encode.sh", args); }

// ffprobe's codec and container, as `codec_name=...\nformat_name=...\n`.
std::string format_of(const fs::path& video) {
    return run_shell("ffprobe -v error -show_entries stream=codec_name -show_entries format=format_name "
                     "-of default=nw=1 " +
                     video.string())
        .out;
}

// ffprobe's key=value lines for the video stream's `entries` (frames counted).
std::string probe_entries(const fs::path& video, const std::string& entries) {
    return run_shell("ffprobe -v error -select_streams v:0 -count_frames -show_entries " + entries +
                     " -of default=nw=1 " + video.string())
        .out;
}

std::string frame_rate(const fs::path& video) { return probe_entries(video, "stream=r_frame_rate"); }

const std::string kSupported = "supported: .mp4 (H.264), .webm (VP9), .gif, .mov (H.264)\n";

TEST(EncodeCli, TheExtensionPicksTheFormat) {
    const fs::path dir = tiny_movie("encode_formats");
    const fs::path frames = render_frames(dir);
    const fs::path out = dir / "v";
    fs::create_directories(out);
    const std::string h264 = "codec_name=h264\nformat_name=mov,mp4,m4a,3gp,3g2,mj2\n";
    const std::string gif = "codec_name=gif\nformat_name=gif\n";
    struct Case {
        std::string file, probed, label;
    };
    for (const Case& c : {Case{"m.mp4", h264, "MP4, H.264"},
                          Case{"m.webm", "codec_name=vp9\nformat_name=matroska,webm\n", "WebM, VP9"},
                          Case{"m.gif", gif, "GIF"},
                          Case{"m.mov", h264, "QuickTime, H.264"},
                          Case{"UPPER.GIF", gif, "GIF"}}) {  // the extension in any case
        const fs::path video = out / c.file;
        const auto r = encode(frames.string() + " " + video.string() + " --fps 12");
        ASSERT_EQ(r.status, 0) << c.file << ": " << r.err;
        EXPECT_EQ(r.out, "encoded 12 frames at 12 fps into " + video.string() + " (" + c.label + ")\n");
        EXPECT_EQ(r.err, "") << c.file;
        EXPECT_EQ(format_of(video), c.probed) << c.file;
        EXPECT_EQ(probe_entries(video, "stream=width,height,nb_read_frames"), "width=64\nheight=64\nnb_read_frames=12\n")
            << c.file;
    }
    // MP4 and QuickTime share ffprobe's demuxer; their brands tell them apart.
    EXPECT_EQ(run_shell("ffprobe -v error -show_entries format_tags=major_brand -of default=nw=1 " +
                        (out / "m.mp4").string())
                  .out,
              "TAG:major_brand=isom\n");
    EXPECT_EQ(run_shell("ffprobe -v error -show_entries format_tags=major_brand -of default=nw=1 " +
                        (out / "m.mov").string())
                  .out,
              "TAG:major_brand=qt  \n");
    for (const char* name : {"m.mp4", "m.webm", "m.mov"})
        EXPECT_EQ(probe_entries(out / name, "stream=pix_fmt"), "pix_fmt=yuv420p\n") << name;
    EXPECT_EQ(frame_rate(out / "m.webm"), "r_frame_rate=12/1\n");
    // Renamed into place: no temporaries left.
    EXPECT_EQ(files_in(out), (std::vector<std::string>{"UPPER.GIF", "m.gif", "m.mov", "m.mp4", "m.webm"}));
}

TEST(EncodeCli, OtherExtensionsAreRefusedBeforeAnythingRuns) {
    const fs::path dir = tiny_movie("encode_ext");
    const fs::path frames = render_frames(dir);
    for (const char* name : {"x.avi", "x.mkv", "x", "x.mp4.part"}) {
        const fs::path video = dir / name;
        const auto r = encode(frames.string() + " " + video.string() + " --fps 12");
        EXPECT_EQ(r.status, 2) << name;
        EXPECT_EQ(r.err, "encode.sh: error: cannot write '" + video.string() +
                             "': the output's extension picks the format; " + kSupported)
            << name;
        EXPECT_EQ(r.out, "") << name;
    }
    // Before the frames are looked at: a missing folder is not what it reports.
    const auto r = encode((dir / "missing").string() + " " + (dir / "x.avi").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: cannot write '" + (dir / "x.avi").string() +
                         "': the output's extension picks the format; " + kSupported);
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"f", "scene.yaml", "tiny.yaml"}));  // nothing written
}

TEST(EncodeCli, TheFpsComesFromTheMovieAndFpsWins) {
    const fs::path dir = tiny_movie("encode_fps", 10);  // 10 frames at 10 fps
    const fs::path frames = render_frames(dir);
    const std::string movie = " --movie " + (dir / "tiny.yaml").string();

    auto r = encode(frames.string() + " " + (dir / "m.mp4").string() + movie);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");  // no warning: the fps is the movie's
    EXPECT_EQ(r.out, "encoded 10 frames at 10 fps into " + (dir / "m.mp4").string() + " (MP4, H.264)\n");
    EXPECT_EQ(frame_rate(dir / "m.mp4"), "r_frame_rate=10/1\n");

    // --fps wins over the movie, wherever the options stand.
    r = encode("--fps 25" + movie + " " + frames.string() + " " + (dir / "m25.webm").string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(frame_rate(dir / "m25.webm"), "r_frame_rate=25/1\n");
    r = encode(frames.string() + " " + (dir / "m24.mov").string() + movie + " --fps 24");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(frame_rate(dir / "m24.mov"), "r_frame_rate=24/1\n");

    // A scene is not a movie.
    r = encode(frames.string() + " " + (dir / "s.mp4").string() + " --movie " + (dir / "scene.yaml").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: --movie " + (dir / "scene.yaml").string() +
                         ": not a movie file (a scene has no fps)\n");
    EXPECT_FALSE(fs::exists(dir / "s.mp4"));
}

TEST(EncodeCli, WithoutMovieOrFpsItWarnsAndTakes30) {
    const fs::path dir = tiny_movie("encode_default_fps");
    const fs::path frames = render_frames(dir);
    fs::remove(frames / "frame_movie.txt");  // the movie's lines `frames` leaves: not here
    const auto r = encode(frames.string() + " " + (dir / "d.mp4").string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(frame_rate(dir / "d.mp4"), "r_frame_rate=30/1\n");
    EXPECT_EQ(r.err.rfind("encode.sh: warning: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;  // one line
    for (const char* words : {"30 fps", "--movie", "--fps"})
        EXPECT_NE(r.err.find(words), std::string::npos) << words << " in " << r.err;
}

TEST(EncodeCli, TheFramesMovieFileGivesTheFpsAndTheFrameCount) {
    const fs::path dir = tiny_movie("encode_sidecar");  // 12 frames
    const fs::path frames = render_frames(dir);
    std::ofstream(frames / "frame_movie.txt") << "movie: tiny.yaml\nfps: 8\nframes: 12\n";
    auto r = encode(frames.string() + " " + (dir / "s.webm").string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_EQ(frame_rate(dir / "s.webm"), "r_frame_rate=8/1\n");
    r = encode(frames.string() + " " + (dir / "s5.mp4").string() + " --fps 5");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(frame_rate(dir / "s5.mp4"), "r_frame_rate=5/1\n");

    // Its frame count is checked, as the movie's.
    std::ofstream(frames / "frame_movie.txt") << "fps: 8\nframes: 10\n";
    r = encode(frames.string() + " " + (dir / "x.mp4").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: " + frames.string() + " holds frames past the movie's end (10 frames, from " +
                         (frames / "frame_movie.txt").string() +
                         "): frame_0010.png is the first; remove them, or render into a fresh folder (firsthit frames --clean)\n");
    std::ofstream(frames / "frame_movie.txt") << "fps: 8\nframes: 14\n";
    r = encode(frames.string() + " " + (dir / "x.mp4").string() + " --fps 8");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: " + frames.string() + " holds 12 of the movie's 14 frames (from " +
                         (frames / "frame_movie.txt").string() +
                         "): frame_0012.png to frame_0013.png are missing (render the missing frames with "
                         "'firsthit frames MOVIE --resume')\n");
    // A movie.txt without its numbers is refused, not guessed around.
    std::ofstream(frames / "frame_movie.txt") << "fps: 8\n";
    r = encode(frames.string() + " " + (dir / "x.mp4").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("'frames: N'"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.mp4"));
}

TEST(EncodeCli, FramesBeyondTheMoviesEndAreRefused) {
    // Stale frames of an earlier, longer render of the same folder.
    const fs::path dir = tiny_movie("encode_extra");  // 12 frames
    const fs::path frames = render_frames(dir);
    fs::copy_file(frames / "frame_0000.png", frames / "frame_0015.png");
    fs::copy_file(frames / "frame_0000.png", frames / "frame_0012.png");
    const std::string movie = (dir / "tiny.yaml").string();
    for (const char* name : {"x.mp4", "x.gif"}) {
        const auto r = encode(frames.string() + " " + (dir / name).string() + " --movie " + movie);
        EXPECT_EQ(r.status, 2) << name;
        EXPECT_EQ(r.err, "encode.sh: error: " + frames.string() + " holds frames past the movie's end (12 frames, from " +
                             movie + "): frame_0012.png is the first; remove them, or render into a fresh folder (firsthit frames --clean)\n")
            << name;
    }
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"f", "scene.yaml", "tiny.yaml"}));  // nothing written
    // Without them, the same command encodes.
    fs::remove(frames / "frame_0012.png");
    fs::remove(frames / "frame_0015.png");
    const auto r = encode(frames.string() + " " + (dir / "x.mp4").string() + " --movie " + movie);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(probe_entries(dir / "x.mp4", "stream=nb_read_frames"), "nb_read_frames=12\n");
}

TEST(EncodeCli, TooFewFramesAreRefusedUntilResumed) {
    const fs::path dir = tiny_movie("encode_few");  // 12 frames
    const fs::path frames = render_frames(dir, "--range 0:10");
    const std::string movie = (dir / "tiny.yaml").string();
    const std::string encode_args = frames.string() + " " + (dir / "x.webm").string() + " --movie " + movie;
    auto r = encode(encode_args);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: " + frames.string() + " holds 10 of the movie's 12 frames (from " + movie +
                         "): frame_0010.png to frame_0011.png are missing (render the missing frames with "
                         "'firsthit frames MOVIE --resume')\n");
    render_frames(dir, "--range 10:11");
    r = encode(encode_args);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: " + frames.string() + " holds 11 of the movie's 12 frames (from " + movie +
                         "): frame_0011.png is missing (render the missing frames with "
                         "'firsthit frames MOVIE --resume')\n");
    EXPECT_FALSE(fs::exists(dir / "x.webm"));
    render_frames(dir, "--resume");
    r = encode(encode_args);
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(probe_entries(dir / "x.webm", "stream=nb_read_frames"), "nb_read_frames=12\n");
}

// A frame that is no PNG, or of another size, is refused before ffmpeg
// runs; one whose data is cut short stops ffmpeg (-xerror) in one line.
// ffmpeg once skipped the first and scaled the second: exit 0, a movie a
// frame short or stretched. Nothing is written either way, and no raw
// frames at all is no video.
TEST(EncodeCli, BrokenFramesAndNoFramesAreRefused) {
    const fs::path dir = tiny_movie("encode_broken");  // 12 frames, 64 x 64
    const fs::path frames = render_frames(dir);
    const std::string out = " " + (dir / "x.mp4").string() + " --fps 12";
    const std::string good = slurp(frames / "frame_0004.png");
    std::ofstream(frames / "frame_0004.png") << "junk\n";
    auto r = encode(frames.string() + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: " + (frames / "frame_0004.png").string() + " is not a PNG file\n");
    ASSERT_EQ(run_firsthit("render " + (dir / "tiny.yaml").string() + " --frame 4 --resolution 32x32 -o " +
                           (frames / "frame_0004.png").string()).status, 0);
    r = encode(frames.string() + out);
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: " + (frames / "frame_0004.png").string() + " is 32x32, the frames before it 64x64\n");
    std::ofstream(frames / "frame_0004.png", std::ios::binary) << good.substr(0, 200);
    r = encode(frames.string() + out);
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err.rfind("encode.sh: error: ffmpeg stopped (exit 1) encoding 12 frames: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    r = run_script("encode.sh", "--raw 64x64" + out + " </dev/null");
    EXPECT_EQ(r.status, 1);
    EXPECT_EQ(r.err, "encode.sh: error: ffmpeg wrote no frame into " + (dir / "x.mp4").string() + ": no frames?\n");
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"f", "scene.yaml", "tiny.yaml"}));  // nothing written
}

// Blender's pattern, whatever its run of '#' (a greedy prefix once took
// '###' of 'b_####.png' and called it two numbers), and folders whose names
// hold '%' or '#'.
TEST(EncodeCli, PatternsAndFolderNamesAsUsersWriteThem) {
    const fs::path dir = tiny_movie("encode_names");
    ASSERT_EQ(run_firsthit("frames " + (dir / "tiny.yaml").string() + " --quiet --out '" +
                           (dir / "p" / "b_####.png").string() + "'").status, 0);
    auto r = encode("'" + (dir / "p" / "b_####.png").string() + "' " + (dir / "p.mp4").string() + " --fps 12");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(probe_entries(dir / "p.mp4", "stream=nb_read_frames"), "nb_read_frames=12\n");
    for (const std::string folder : {"100%", "take#1"}) {
        fs::create_directories(dir / folder);
        fs::copy_file(dir / "p" / "b_0000.png", dir / folder / "frame_0000.png");
        r = encode("'" + (dir / folder).string() + "' " + (dir / "q.gif").string() + " --fps 12");
        ASSERT_EQ(r.status, 0) << folder << ": " << r.err;
        EXPECT_EQ(r.out, "encoded 1 frame at 12 fps into " + (dir / "q.gif").string() + " (GIF)\n");
    }
}

TEST(EncodeCli, RawFramesTakeTheSameFormats) {
    const fs::path dir = tiny_movie("encode_raw");
    const std::string movie = (dir / "tiny.yaml").string();
    struct Case {
        std::string file, probed, label;
    };
    for (const Case& c : {Case{"r.gif", "codec_name=gif\nformat_name=gif\n", "GIF"},
                          Case{"r.webm", "codec_name=vp9\nformat_name=matroska,webm\n", "WebM, VP9"},
                          Case{"r.mov", "codec_name=h264\nformat_name=mov,mp4,m4a,3gp,3g2,mj2\n", "QuickTime, H.264"}}) {
        const fs::path video = dir / c.file;
        const auto r = run_shell(std::string(FIRSTHIT_BINARY) + " frames " + movie + " --quiet --out " +
                                 (dir / ("frames_" + c.file)).string() + " --raw-video - | FIRSTHIT=" +
                                 FIRSTHIT_BINARY + " " + source_path("scripts/encode.sh") + " --raw 64x64 " +
                                 video.string() + " --movie " + movie);
        ASSERT_EQ(r.status, 0) << c.file << ": " << r.err;
        EXPECT_EQ(r.out, "encoded raw frames from standard input at 12 fps into " + video.string() + " (" + c.label +
                             ")\n");
        EXPECT_EQ(format_of(video), c.probed) << c.file;
        EXPECT_EQ(probe_entries(video, "stream=nb_read_frames"), "nb_read_frames=12\n") << c.file;
    }
    EXPECT_EQ(frame_rate(dir / "r.webm"), "r_frame_rate=12/1\n");
    const auto r = run_script("encode.sh", "--raw 64x64 " + (dir / "r.avi").string() + " --fps 12 </dev/null");
    EXPECT_EQ(r.status, 2);
    EXPECT_EQ(r.err, "encode.sh: error: cannot write '" + (dir / "r.avi").string() +
                         "': the output's extension picks the format; " + kSupported);
    EXPECT_FALSE(fs::exists(dir / "r.avi"));
}

}  // namespace
}  // namespace fh::test
