// Crash safety of `firsthit frames`, with real signals on real runs: SIGKILL
// at any moment leaves only whole frames; SIGINT and SIGTERM stop the run
// within a second, leave no temporaries and exit non-zero; `--resume` then
// renders exactly the missing frames, byte-identical to an uninterrupted run.
#include <gtest/gtest.h>

#include <unistd.h>

#include <regex>

#include "cli/run_command.h"
#include "files/atomic_file.h"
#include "images/png_writer.h"
#include "support/png_read.h"

namespace fh::test {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

constexpr int kFrames = 60;
// Frames small enough for the sanitizers' slower runs, big enough that a run
// takes long enough to be interrupted in the middle.
constexpr int kSide = kSlowdown > 1 ? 48 : 96;
constexpr int kSpp = kSlowdown > 1 ? 2 : 8;

// The report's scene at side x side and a 60-frame orbit of it at `spp`.
fs::path interrupted_movie_dir(const std::string& name, int side, int spp) {
    const fs::path dir = fresh_dir(name);
    std::string scene = slurp(source_path("animations/scene.yaml"));
    scene = std::regex_replace(scene, std::regex("width: 800"), "width: " + std::to_string(side));
    scene = std::regex_replace(scene, std::regex("height: 800"), "height: " + std::to_string(side));
    std::ofstream(dir / "scene.yaml") << scene;
    std::ofstream(dir / "movie.yaml") << "scene: scene.yaml\ncamera: perspective\nlights: [ambient, spot]\n"
                                         "fps: 30\nseconds: 2\n"
                                         "animate:\n  view_point:\n    orbit: {center: [-10, -10, 16], "
                                         "sin: [20, 0, 0], cos: [0, 0, 15]}\n"
                                         "  look_at: {toward: [0, 0, 0]}\n"
                                         "render: {samples_per_pixel: " + std::to_string(spp) + "}\n";
    return dir;
}

// The names in a folder, sorted, read without throwing while firsthit may
// still be writing or renaming files in it.
std::vector<std::string> names_so_far(const fs::path& dir) {
    std::vector<std::string> names;
    std::error_code ec;
    for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
        names.push_back(it->path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

const std::regex kFrameName("frame_[0-9]{4}\\.png");
const std::regex kTemporaryName("frame_[0-9]{4}\\.png\\.tmp-.+-[0-9]+-[0-9]+");

int count_frames(const fs::path& dir) {
    int n = 0;
    for (const auto& name : names_so_far(dir)) n += std::regex_match(name, kFrameName);
    return n;
}

// Every frame file in `dir` is a whole, valid PNG and has the bytes of the
// uninterrupted run's frame; anything else is a temporary. Returns the
// number of temporaries.
int check_only_whole_frames(const fs::path& dir, const fs::path& reference) {
    int temporaries = 0;
    for (const auto& name : names_so_far(dir)) {
        if (std::regex_match(name, kTemporaryName)) {
            ++temporaries;
            continue;
        }
        if (name == "frame_movie.txt") continue;  // the movie's lines, written before any frame
        EXPECT_TRUE(std::regex_match(name, kFrameName)) << "unexpected file " << name;
        EXPECT_TRUE(is_complete_png((dir / name).string())) << name;
        EXPECT_GT(read_png((dir / name).string()).width, 0) << name;
        EXPECT_EQ(slurp(dir / name), slurp(reference / name)) << name;
    }
    return temporaries;
}

// Starts `frames` on the movie into `out`; waits until at least `frames`
// frames exist (or the run ends, which the caller checks).
Background start_and_wait(const fs::path& dir, const fs::path& out, int frames,
                          const std::vector<std::string>& extra = {}) {
    std::vector<std::string> args{"frames", (dir / "movie.yaml").string(), "--quiet", "--threads", "2",
                                  "--out", out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const Background b = spawn_firsthit(args, dir);
    EXPECT_GT(b.pid, 0);
    const auto end = std::chrono::steady_clock::now() + 60s * kSlowdown;
    while (count_frames(out) < frames && std::chrono::steady_clock::now() < end) {
        int status = 0;
        if (waitpid(b.pid, &status, WNOHANG) == b.pid) {
            ADD_FAILURE() << "the run ended before it could be interrupted: " << slurp(b.err);
            return Background{};
        }
        std::this_thread::sleep_for(1ms);
    }
    return b;
}

// --resume renders exactly the frames missing from `out`, and the folder
// then equals the reference run's, byte for byte, with no temporaries left.
void resume_and_compare(const fs::path& dir, const fs::path& out, const fs::path& reference) {
    const int present = count_frames(out);
    const auto r = run_firsthit("frames " + (dir / "movie.yaml").string() + " --quiet --resume --stats --out " +
                                out.string());
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("frames: " + std::to_string(kFrames - present) + "\n"), std::string::npos)
        << present << " frames were present; " << r.out;
    EXPECT_EQ(names_so_far(out), names_so_far(reference));
    for (const auto& name : names_so_far(reference)) EXPECT_EQ(slurp(out / name), slurp(reference / name)) << name;
}

fs::path reference_run(const fs::path& dir) {
    const fs::path ref = dir / "reference";
    const auto r = run_firsthit("frames " + (dir / "movie.yaml").string() + " --quiet --threads 1 --out " +
                                ref.string());
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(count_frames(ref), kFrames);
    return ref;
}

TEST(InterruptCli, SigkillLeavesOnlyWholeFramesAndResumeCompletesThem) {
    const fs::path dir = interrupted_movie_dir("kill", kSide, kSpp);
    const fs::path ref = reference_run(dir);
    const fs::path out = dir / "out";
    // Killed twice, the second time while resuming, then resumed to the end.
    for (const int at_least : {5, 25}) {
        const Background b = start_and_wait(dir, out, at_least, {"--resume"});
        ASSERT_GT(b.pid, 0);
        ASSERT_EQ(kill(b.pid, SIGKILL), 0);
        const int status = wait_for(b.pid, 10s * kSlowdown);
        ASSERT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
        EXPECT_LT(count_frames(out), kFrames) << "killed too late to test anything";
        check_only_whole_frames(out, ref);
    }
    // A temporary left by a dead process of this machine (no process has
    // PID 999999999) is removed by the next run.
    const std::string tmp = fs::path(temporary_name((out / "frame_0059.png").string(), 0)).filename().string();
    const std::string host_part = tmp.substr(0, tmp.rfind('-', tmp.rfind('-') - 1));
    std::ofstream(out / (host_part + "-999999999-0")) << "half a frame";
    resume_and_compare(dir, out, ref);
}

TEST(InterruptCli, SigintAndSigtermStopWithinASecondAndResumeCompletesThem) {
    const fs::path dir = interrupted_movie_dir("sigint", kSide, kSpp);
    const fs::path ref = reference_run(dir);
    for (const int sig : {SIGINT, SIGTERM}) {
        SCOPED_TRACE(sig == SIGINT ? "SIGINT" : "SIGTERM");
        const fs::path out = dir / (sig == SIGINT ? "int" : "term");
        const Background b = start_and_wait(dir, out, 4);
        ASSERT_GT(b.pid, 0);
        const auto sent = std::chrono::steady_clock::now();
        ASSERT_EQ(kill(b.pid, sig), 0);
        const int status = wait_for(b.pid, 10s * kSlowdown);
        const auto took = std::chrono::steady_clock::now() - sent;
        ASSERT_TRUE(WIFEXITED(status)) << status;
        EXPECT_EQ(WEXITSTATUS(status), 128 + sig);
        EXPECT_LT(took, 1s * kSlowdown);
        const std::string err = slurp(b.err);
        EXPECT_NE(err.find("firsthit: interrupted after "), std::string::npos) << err;
        EXPECT_NE(err.find("run again with --resume"), std::string::npos) << err;
        EXPECT_LT(count_frames(out), kFrames) << "interrupted too late to test anything";
        EXPECT_EQ(check_only_whole_frames(out, ref), 0) << "temporaries left";
        resume_and_compare(dir, out, ref);
    }
}

// `frames` on the movie in dir with 2 threads, returned once its workers run:
// the signals are taken over before the first thread starts, so once there
// are threads a signal no longer kills the process outright.
Background start_slow_frames(const fs::path& dir, const fs::path& out) {
    const Background b = spawn_firsthit({"frames", (dir / "movie.yaml").string(), "--quiet", "--threads", "2",
                                         "--out", out.string()},
                                        dir);
    if (b.pid <= 0) return b;
    const auto end = std::chrono::steady_clock::now() + 30s * kSlowdown;
    while (thread_count(b.pid) < 3 && std::chrono::steady_clock::now() < end) std::this_thread::sleep_for(1ms);
    std::this_thread::sleep_for(100ms);
    return b;
}

TEST(InterruptCli, SlowFramesInFlightAreAbandonedWithinASecond) {
    // Each frame takes seconds (192 x 192 pixels at 4096 samples): the run does not
    // wait for them, writes nothing and still stops within a second.
    const fs::path dir = interrupted_movie_dir("slow", 192, 4096);
    const fs::path out = dir / "out";
    const Background b = start_slow_frames(dir, out);
    ASSERT_GT(b.pid, 0);
    const auto sent = std::chrono::steady_clock::now();
    ASSERT_EQ(kill(b.pid, SIGTERM), 0);
    const int status = wait_for(b.pid, 20s * kSlowdown);
    const auto took = std::chrono::steady_clock::now() - sent;
    ASSERT_TRUE(WIFEXITED(status)) << status << " " << slurp(b.err);
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM);
    EXPECT_LT(took, 1s * kSlowdown);
    EXPECT_NE(slurp(b.err).find("frames in flight abandoned"), std::string::npos) << slurp(b.err);
    EXPECT_EQ(names_so_far(out), std::vector<std::string>{"frame_movie.txt"});  // no frame
}

TEST(InterruptCli, SecondSignalStopsAtOnce) {
    const fs::path dir = interrupted_movie_dir("twice", 192, 4096);
    const fs::path out = dir / "out";
    const Background b = start_slow_frames(dir, out);
    ASSERT_GT(b.pid, 0);
    const auto sent = std::chrono::steady_clock::now();
    ASSERT_EQ(kill(b.pid, SIGINT), 0);
    std::this_thread::sleep_for(50ms);
    ASSERT_EQ(kill(b.pid, SIGINT), 0);
    const int status = wait_for(b.pid, 20s * kSlowdown);
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT);
    EXPECT_LT(std::chrono::steady_clock::now() - sent, 400ms * kSlowdown);
    EXPECT_EQ(names_so_far(out), std::vector<std::string>{"frame_movie.txt"});  // no frame
}

}  // namespace
}  // namespace fh::test
