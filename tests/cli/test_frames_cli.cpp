// firsthit frames and the movie scripts (encode.sh, make_movie.sh,
// make_movies.sh) end to end, on tiny movies (64 x 64, 12 frames, and a few
// other sizes) made from the report's scene.
#include <gtest/gtest.h>

#include "cli/small_movie.h"
#include "video/yuv420.h"
#include "render/image_compare.h"
#include "support/png_read.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;

std::string frames_command(const fs::path& dir, const std::string& extra) {
    return "frames " + (dir / "tiny.yaml").string() + " --quiet " + extra;
}

TEST(FramesCli, RendersEveryFrameWhole) {
    const fs::path dir = tiny_movie("frames_all");
    const auto r = run_firsthit(frames_command(dir, "--out " + (dir / "f").string()));
    ASSERT_EQ(r.status, 0) << r.err;
    const auto names = frames_in(dir / "f");
    ASSERT_EQ(names.size(), 12u);
    EXPECT_EQ(names.front(), "frame_0000.png");
    EXPECT_EQ(names.back(), "frame_0011.png");
    EXPECT_EQ(read_png((dir / "f" / "frame_0007.png").string()).width, 64);
}

TEST(FramesCli, RangeShardsAndResumeGiveTheSameBytesAsOneRun) {
    const fs::path dir = tiny_movie("frames_parts");
    ASSERT_EQ(run_firsthit(frames_command(dir, "--out " + (dir / "full").string())).status, 0);

    ASSERT_EQ(run_firsthit(frames_command(dir, "--range 3:6 --out " + (dir / "range").string())).status, 0);
    EXPECT_EQ(frames_in(dir / "range"),
              (std::vector<std::string>{"frame_0003.png", "frame_0004.png", "frame_0005.png"}));

    for (int k = 0; k < 3; ++k)
        ASSERT_EQ(run_firsthit(frames_command(dir, "--shard " + std::to_string(k) + "/3 --threads 1 --out " +
                                               (dir / "shards").string()))
                      .status,
                  0);
    ASSERT_EQ(frames_in(dir / "shards"), frames_in(dir / "full"));
    for (const auto& name : frames_in(dir / "full"))
        EXPECT_EQ(slurp(dir / "shards" / name), slurp(dir / "full" / name)) << name;

    // Lose two frames and truncate a third; --resume renders exactly those.
    fs::remove(dir / "shards" / "frame_0002.png");
    fs::remove(dir / "shards" / "frame_0007.png");
    fs::resize_file(dir / "shards" / "frame_0009.png", 100);
    const auto r = run_firsthit(frames_command(dir, "--resume --stats --out " + (dir / "shards").string()));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("frames: 3\n"), std::string::npos) << r.out;
    for (const auto& name : frames_in(dir / "full"))
        EXPECT_EQ(slurp(dir / "shards" / name), slurp(dir / "full" / name)) << name;
}

// --resume and --shard keep the frames already there, so they must be of
// the same render: another sample count, depth, precision or camera is
// refused (it once mixed silently); a folder from before frame_movie.txt
// had its render line is taken as it was.
TEST(FramesCli, ResumeRefusesFramesRenderedOtherwise) {
    const fs::path dir = tiny_movie("frames_other_render");
    const std::string out = " --out " + (dir / "f").string();
    ASSERT_EQ(run_firsthit(frames_command(dir, "--range 0:6" + out)).status, 0);
    EXPECT_NE(slurp(dir / "f" / "frame_movie.txt").find("\nrender: camera perspective, 1 sample, depth 5, double\n"),
              std::string::npos);
    for (const std::string other : {"--spp 2", "--depth 1", "--precision float", "--adaptive"}) {
        const auto r = run_firsthit(frames_command(dir, "--resume " + other + out));
        EXPECT_EQ(r.status, 2) << other;
        EXPECT_NE(r.err.find("Pass --clean"), std::string::npos) << other << ": " << r.err;
    }
    const std::string movie_file = slurp(dir / "f" / "frame_movie.txt");
    std::ofstream(dir / "f" / "frame_movie.txt") << movie_file.substr(0, movie_file.find("render: "));
    const auto r = run_firsthit(frames_command(dir, "--resume --stats" + out));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("frames: 6\n"), std::string::npos) << r.out;
}

TEST(FramesCli, OneFrameFromRenderEqualsTheSameFrameOfTheMovie) {
    const fs::path dir = tiny_movie("frames_single");
    ASSERT_EQ(run_firsthit(frames_command(dir, "--out " + (dir / "f").string())).status, 0);
    ASSERT_EQ(run_firsthit("render " + (dir / "tiny.yaml").string() + " --frame 5 -o " +
                           (dir / "one.png").string())
                  .status,
              0);
    EXPECT_EQ(slurp(dir / "one.png"), slurp(dir / "f" / "frame_0005.png"));
}

TEST(FramesCli, BadSelectionsAreUsageErrors) {
    const fs::path dir = tiny_movie("frames_bad");
    const std::string out = " --out " + (dir / "f").string();
    EXPECT_EQ(run_firsthit(frames_command(dir, "--range 0:13" + out)).err,
              "firsthit: error: --range 0:13: frame 12 is past the movie's end: its 12 frames are 0 to 11\n");
    EXPECT_EQ(run_firsthit(frames_command(dir, "--shard 3/3" + out)).err,
              "firsthit: error: --shard 3/3: need 0 <= K < N\n");
    EXPECT_EQ(run_firsthit(frames_command(dir, "--shard 3/3" + out)).status, 2);
    EXPECT_EQ(run_firsthit("frames " + source_path("animations/scene.yaml")).status, 2);
}

TEST(FramesCli, RawVideoIsEveryFrameInOrder) {
    // Three workers finish frames out of order; the stream must not be.
    const fs::path dir = tiny_movie("frames_raw");
    const auto r = run_firsthit(frames_command(dir, "--threads 3 --out " + (dir / "f").string() +
                                                " --raw-video " + (dir / "raw.rgb").string()));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string raw = slurp(dir / "raw.rgb");
    constexpr size_t kFrameBytes = 64 * 64 * 3;
    ASSERT_EQ(raw.size(), 12 * kFrameBytes);
    for (int i = 0; i < 12; ++i) {
        const Image png = read_png((dir / "f" / frames_in(dir / "f")[size_t(i)]).string());
        EXPECT_EQ(raw.compare(size_t(i) * kFrameBytes, kFrameBytes,
                              reinterpret_cast<const char*>(png.rgb.data()), kFrameBytes),
                  0)
            << "frame " << i;
    }
}

// Raw video may go to a named pipe (an encoder reading it) or a device, whose
// folder need not be writable: the checks before rendering let them through.
TEST(FramesCli, RawVideoGoesToANamedPipeOrADevice) {
    const fs::path dir = tiny_movie("frames_raw_pipe");
    const fs::path fifo = dir / "pipe", got = dir / "got.rgb";
    const auto r = run_shell("mkfifo " + fifo.string() + " && { cat " + fifo.string() + " > " + got.string() +
                             " & } && " + std::string(FIRSTHIT_BINARY) + " " +
                             frames_command(dir, "--out " + (dir / "f").string() + " --raw-video " + fifo.string()) +
                             "; s=$?; [ $s -eq 0 ] || : > " + fifo.string() + "; wait; exit $s");  // cat never waits on
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(fs::file_size(got), 12u * 64 * 64 * 3);
    const auto null = run_firsthit(frames_command(dir, "--out " + (dir / "g").string() + " --raw-video /dev/null"));
    EXPECT_EQ(null.status, 0) << null.err;
}

TEST(FramesCli, RawVideoInYuv420pIsEachFrameConverted) {
    const fs::path dir = tiny_movie("frames_raw_yuv");
    const auto r = run_firsthit(frames_command(dir, "--threads 3 --out " + (dir / "f").string() + " --raw-video " +
                                                (dir / "raw.yuv").string() + " --raw-pix-fmt yuv420p"));
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string raw = slurp(dir / "raw.yuv");
    constexpr size_t kFrameBytes = 64 * 64 * 3 / 2;
    ASSERT_EQ(raw.size(), 12 * kFrameBytes);
    for (int i = 0; i < 12; ++i) {
        const auto yuv = to_yuv420p(read_png((dir / "f" / frames_in(dir / "f")[size_t(i)]).string()));
        EXPECT_EQ(raw.compare(size_t(i) * kFrameBytes, kFrameBytes, reinterpret_cast<const char*>(yuv.data()),
                              kFrameBytes),
                  0)
            << "frame " << i;
    }
}

TEST(FramesCli, RawVideoErrors) {
    const fs::path dir = tiny_movie("frames_raw_bad");
    const std::string out = " --out " + (dir / "f").string();
    EXPECT_EQ(run_firsthit(frames_command(dir, "--shard 0/2 --raw-video -" + out)).err,
              "firsthit: error: --raw-video streams whole runs of frames: not with --shard or --resume\n");
    EXPECT_EQ(run_firsthit(frames_command(dir, "--stats --raw-video -" + out)).err,
              "firsthit: error: --raw-video - writes frames to standard output: not with --stats\n");
    EXPECT_EQ(run_firsthit(frames_command(dir, "--raw-video " + (dir / "x.raw").string() + " --raw-pix-fmt yuv444p" + out)).err,
              "firsthit: error: --raw-pix-fmt: unknown raw pixel format 'yuv444p' (rgb24 or yuv420p)\n");
    EXPECT_EQ(run_firsthit(frames_command(dir, "--raw-pix-fmt yuv420p" + out)).err,
              "firsthit: error: --raw-pix-fmt goes with --raw-video\n");
    // The encoder goes away: one clear line and a failure, not a SIGPIPE death.
    const auto r = run_shell("bash -c 'set -o pipefail; " + std::string(FIRSTHIT_BINARY) + " " +
                             frames_command(dir, "--raw-video -" + out) + " | head -c 100 >/dev/null'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("cannot write raw video to standard output: the reader closed it"),
              std::string::npos)
        << r.err;
}

TEST(EncodeScript, StreamingWhileRenderingGivesTheSameMp4AsEncodingTheFiles) {
    const fs::path dir = tiny_movie("encode_stream");
    const auto made = run_script("make_movie.sh", (dir / "tiny.yaml").string() + " " + (dir / "out").string());
    ASSERT_EQ(made.status, 0) << made.err;
    ASSERT_EQ(frames_in(dir / "out" / "tiny").size(), 12u);
    const auto r = run_script("encode.sh", (dir / "out" / "tiny").string() +
                              " " + (dir / "files.mp4").string() + " --fps 12");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir / "out" / "tiny.mp4"), slurp(dir / "files.mp4"));
    EXPECT_EQ(files_in(dir / "out"), (std::vector<std::string>{"tiny", "tiny.mp4"}));  // no temporaries
}

TEST(EncodeScript, MakesAnMp4ThatFfprobeReads) {
    const fs::path dir = tiny_movie("encode");
    ASSERT_EQ(run_firsthit(frames_command(dir, "--out " + (dir / "f").string())).status, 0);
    const fs::path mp4 = dir / "tiny.mp4";
    const auto r = run_script("encode.sh", (dir / "f").string() + " " + mp4.string() + " --fps 12");
    ASSERT_EQ(r.status, 0) << r.err;
    const auto probe = run_shell(
        "ffprobe -v error -select_streams v:0 -count_frames -show_entries "
        "stream=codec_name,width,height,pix_fmt,nb_read_frames:format=duration -of "
        "default=noprint_wrappers=1 " +
        mp4.string());
    ASSERT_EQ(probe.status, 0) << probe.err;
    for (const char* line : {"codec_name=h264\n", "width=64\n", "height=64\n", "pix_fmt=yuv420p\n",
                             "nb_read_frames=12\n", "duration=1.000000\n"})
        EXPECT_NE(probe.out.find(line), std::string::npos) << line << " in\n" << probe.out;
}

TEST(EncodeScript, RefusesEmptyFoldersAndGaps) {
    const fs::path dir = tiny_movie("encode_bad");
    fs::create_directories(dir / "empty");
    auto r = run_script("encode.sh", (dir / "empty").string() + " " + (dir / "x.mp4").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("holds no frames"), std::string::npos) << r.err;

    ASSERT_EQ(run_firsthit(frames_command(dir, "--out " + (dir / "f").string())).status, 0);
    fs::remove(dir / "f" / "frame_0004.png");
    r = run_script("encode.sh", (dir / "f").string() + " " + (dir / "x.mp4").string());
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("expected frame_0004.png, found frame_0005.png"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.mp4"));
}

// ffprobe's key=value lines for a video's first stream.
std::string probe_video(const fs::path& mp4) {
    return run_shell("ffprobe -v error -select_streams v:0 -count_frames -show_entries "
                     "stream=width,height,nb_read_frames -of default=noprint_wrappers=1 " +
                     mp4.string())
        .out;
}

TEST(EncodeScript, OneEncoderThreadStreamedOrFromFilesGivesOneMp4) {
    const fs::path dir = tiny_movie("encode_threads");
    const auto made = run_script("make_movie.sh", (dir / "tiny.yaml").string() +
                                 " " + (dir / "out").string() + " --encoder-threads 1 --quiet");
    ASSERT_EQ(made.status, 0) << made.err;
    const auto r = run_script("encode.sh", (dir / "out" / "tiny").string() +
                              " " + (dir / "files.mp4").string() + " --fps 12 --threads 1");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(slurp(dir / "out" / "tiny.mp4"), slurp(dir / "files.mp4"));
    const auto bad = run_script("encode.sh", (dir / "out" / "tiny").string() +
                                " " + (dir / "x.mp4").string() + " --threads 0");
    EXPECT_EQ(bad.status, 2);
    EXPECT_EQ(bad.err, "encode.sh: error: --threads needs a whole number > 0, got '0'\n");
    const auto png_pix_fmt = run_script("encode.sh", (dir / "out" / "tiny").string() + " " + (dir / "x.mp4").string() +
                                        " --pix-fmt yuv420p");
    EXPECT_EQ(png_pix_fmt.err, "encode.sh: error: --pix-fmt is for --raw frames (frame files are PNG)\n");
    const auto bad_pix_fmt = run_shell("FIRSTHIT=" + std::string(FIRSTHIT_BINARY) + " " +
                                       source_path("scripts/encode.sh") + " --raw 64x64 " + (dir / "x.mp4").string() +
                                       " --pix-fmt nv12 </dev/null");
    EXPECT_EQ(bad_pix_fmt.status, 2);
    EXPECT_EQ(bad_pix_fmt.err, "encode.sh: error: --pix-fmt is rgb24 or yuv420p, got 'nv12'\n");
}

TEST(EncodeScript, OddSidesArePaddedToEvenOnBothPaths) {
    // H.264 in yuv420p needs even sides: 33 x 17 frames become 34 x 18.
    const fs::path dir = small_movie("encode_odd", 33, 17, 6, "odd.yaml");
    const auto made = run_script("make_movie.sh", (dir / "odd.yaml").string() +
                                 " " + (dir / "out").string() + " --quiet");
    ASSERT_EQ(made.status, 0) << made.err;
    const auto r = run_script("encode.sh", (dir / "out" / "odd").string() +
                              " " + (dir / "files.mp4").string() + " --fps 6");
    ASSERT_EQ(r.status, 0) << r.err;
    // And streamed as yuv420p, whose chroma planes are 17 x 9.
    const auto yuv = run_script("make_movie.sh", (dir / "odd.yaml").string() + " " + (dir / "yuv").string() +
                                " --raw-pix-fmt yuv420p --quiet");
    ASSERT_EQ(yuv.status, 0) << yuv.err;
    for (const fs::path& mp4 : {dir / "out" / "odd.mp4", dir / "files.mp4", dir / "yuv" / "odd.mp4"})
        EXPECT_EQ(probe_video(mp4), "width=34\nheight=18\nnb_read_frames=6\n") << mp4;
    EXPECT_EQ(slurp(dir / "out" / "odd.mp4"), slurp(dir / "files.mp4"));
}

// A video's frames, decoded to RGB24 and stacked: one image of width x
// (height * frames).
Image decoded(const fs::path& mp4, int width) {
    const std::string rgb =
        run_shell("ffmpeg -hide_banner -loglevel error -nostdin -i " + mp4.string() + " -f rawvideo -pix_fmt rgb24 -")
            .out;
    Image im;
    im.width = width;
    im.height = int(rgb.size() / (3 * size_t(width)));
    im.rgb.assign(rgb.begin(), rgb.end());
    return im;
}

TEST(MakeMovies, RendersAndEncodesMoviesSideBySide) {
    // Two small movies at once, as `make movies` does the report's two.
    const fs::path dir = small_movie("make_movies", 48, 32, 12, "a.yaml");
    std::ofstream(dir / "b.yaml") << std::regex_replace(slurp(dir / "a.yaml"), std::regex("lights: \\[ambient, spot\\]"),
                                                        "lights: [ambient, directional]");
    const auto r = run_script("make_movies.sh", (dir / "out").string() + " " +
                              (dir / "a.yaml").string() + " " + (dir / "b.yaml").string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(files_in(dir / "out"), (std::vector<std::string>{"a", "a.mp4", "b", "b.mp4"}));
    for (const char* name : {"a", "b"}) {
        EXPECT_EQ(frames_in(dir / "out" / name).size(), 12u);
        EXPECT_EQ(probe_video(dir / "out" / (std::string(name) + ".mp4")), "width=48\nheight=32\nnb_read_frames=12\n");
        // Against encoding the frame files with one x264 thread too (ffmpeg
        // converting to yuv420p): both videos are as close to the frames.
        const auto e = run_script("encode.sh", (dir / "out" / name).string() + " " +
                                  (dir / (std::string(name) + "_files.mp4")).string() + " --fps 12 --threads 1");
        ASSERT_EQ(e.status, 0) << e.err;
        Image frames(48, 0);  // the PNGs, stacked as decoded() stacks the video's
        for (const auto& f : frames_in(dir / "out" / name)) {
            const Image im = read_png((dir / "out" / name / f).string());
            frames.rgb.insert(frames.rgb.end(), im.rgb.begin(), im.rgb.end());
            frames.height += im.height;
        }
        ASSERT_EQ(frames.height, 12 * 32);
        const Image streamed_video = decoded(dir / "out" / (std::string(name) + ".mp4"), 48);
        const Image files_video = decoded(dir / (std::string(name) + "_files.mp4"), 48);
        ASSERT_EQ(streamed_video.height, frames.height);
        ASSERT_EQ(files_video.height, frames.height);
        const double streamed = compare_images(streamed_video, frames).rmse;
        const double from_files = compare_images(files_video, frames).rmse;
        EXPECT_LT(streamed, from_files + 0.1) << name;
    }
    EXPECT_NE(slurp(dir / "out" / "a" / "frame_0003.png"), slurp(dir / "out" / "b" / "frame_0003.png"));
}

TEST(MakeMovies, AFailingMovieFailsTheRunAndLeavesNoMp4) {
    const fs::path dir = small_movie("make_movies_bad", 32, 32, 6, "good.yaml");
    std::ofstream(dir / "bad.yaml") << "scene: missing.yaml\ncamera: perspective\n";
    const auto r = run_script("make_movies.sh", (dir / "out").string() + " " +
                              (dir / "good.yaml").string() + " " + (dir / "bad.yaml").string());
    EXPECT_NE(r.status, 0);
    EXPECT_NE(r.err.find("missing.yaml"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "out" / "bad.mp4"));
    EXPECT_TRUE(fs::exists(dir / "out" / "good.mp4"));  // the other movie is not harmed
}

// make_movie.sh checks its options and every frame of the movie (firsthit
// info) before it touches the last render: a bad option or a value that
// goes wrong at frame 4 once left that render's folder half emptied. Each
// is one line, exit 2, the old frames and movie kept.
TEST(MakeMovies, MistakesAreOneLineAndKeepTheLastRender) {
    const fs::path dir = small_movie("make_movie_checks", 32, 32, 6, "m.yaml");
    const std::string out = " " + (dir / "out").string();
    ASSERT_EQ(run_script("make_movie.sh", (dir / "m.yaml").string() + out + " --quiet").status, 0);
    const std::string movie = slurp(dir / "m.yaml");
    const std::string frame_3 = slurp(dir / "out" / "m" / "frame_0003.png"), mp4 = slurp(dir / "out" / "m.mp4");
    std::ofstream(dir / "m.yaml") << movie << "  lights.ambient.intensity: {keyframes: [{frame: 0, value: 1}, "
                                             "{frame: 3, value: 0.001}, {frame: 5, value: 0.001}], interpolation: catmull_rom}\n";
    const std::string bad_frame = run_firsthit("info " + (dir / "m.yaml").string()).err;
    EXPECT_NE(bad_frame.find(" at frame 4; it must be >= 0"), std::string::npos) << bad_frame;
    for (const auto& [args, line] : std::vector<std::pair<std::string, std::string>>{
             {"m.yaml" + out, bad_frame},
             {"scene.yaml" + out, "make_movie.sh: error: " + (dir / "scene.yaml").string() +
                                      " is a scene, not a movie (a movie file has a 'scene:' key)\n"},
             {"m.yaml" + out + " --encoder-threads 0", "make_movie.sh: error: --encoder-threads needs a whole number > 0, got '0'\n"},
             {"m.yaml" + out + " --raw-pix-fmt rgb", "make_movie.sh: error: --raw-pix-fmt is rgb24 or yuv420p, got 'rgb'\n"}}) {
        const auto r = run_script("make_movie.sh", (dir / args).string());
        EXPECT_EQ(r.status, 2) << args;
        EXPECT_EQ(r.err, line) << args;
        EXPECT_EQ(frames_in(dir / "out" / "m").size(), 6u) << args;
        EXPECT_EQ(slurp(dir / "out" / "m" / "frame_0003.png"), frame_3) << args;
        EXPECT_EQ(slurp(dir / "out" / "m.mp4"), mp4) << args;
    }
}

TEST(MakeMovies, TermStopsEveryRendererAndEncoderAndLeavesNoMp4) {
    // Two movies slow enough to be caught in the middle.
    const std::string slow = "render: {samples_per_pixel: 8}\n";
    const fs::path dir = small_movie("make_movies_term", 96, 96, 60, "a.yaml", slow);
    std::ofstream(dir / "b.yaml") << slurp(dir / "a.yaml");
    const fs::path out = dir / "out";
    const auto r = run_shell(
        "bash -c 'FIRSTHIT=" + std::string(FIRSTHIT_BINARY) + " " + source_path("scripts/make_movies.sh") + " " +
        out.string() + " " + (dir / "a.yaml").string() + " " + (dir / "b.yaml").string() + " & pid=$!; " +
        "for i in $(seq 2000); do [ -e " + (out / "a" / "frame_0002.png").string() + " ] && break; sleep 0.01; done; " +
        "kill -TERM $pid; wait $pid; echo status=$?; sleep 1; " +
        // [f]: the pattern must not match the shell that runs it.
        "echo running=$(pgrep -fc -- \"[f]irsthit frames .*" + out.string() + "|[f]fmpeg .*" + out.string() +
        "|[m]ake_movie.sh .*" + out.string() + "\" || true)'");
    EXPECT_NE(r.out.find("status=143\n"), std::string::npos) << r.out << r.err;
    EXPECT_NE(r.out.find("running=0\n"), std::string::npos) << r.out;  // no renderer, no encoder
    EXPECT_NE(r.err.find("make_movies.sh: stopped by SIGTERM"), std::string::npos) << r.err;
    for (const auto& name : files_in(out)) EXPECT_EQ(name.find(".mp4"), std::string::npos) << name;
}

}  // namespace
}  // namespace fh::test
