// firsthit frames MOVIE: every frame of a movie (or a range or shard of them)
// to DIR/frame_NNNN.png. Frames are spread over the pool one per worker: each
// worker renders its frame on its own and encodes the PNG, so PNG encoding
// runs beside rendering instead of stalling it.
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <optional>
#include <shared_mutex>

#include <unistd.h>

#include "anim/frame_selection.h"
#include "anim/movie.h"
#include "cli/commands.h"
#include "cli/interrupt.h"
#include "cli/job.h"
#include "cli/progress.h"
#include "cli/stats_output.h"
#include "io/input_error.h"
#include "io/movie_loader.h"
#include "io/png_writer.h"
#include "io/raw_video_writer.h"
#include "io/scene_loader.h"

namespace fh {

const char* const kFramesHelp =
    R"(usage: firsthit frames MOVIE [options]

Renders the frames of a movie file to DIR/frame_0000.png, frame_0001.png, ...
Each file is written under a temporary name and renamed, so a frame file is
always whole. On a terminal a progress line shows frames done, frames per
second and the time left.

  --out DIR        where the frames go (default: output/NAME, NAME the movie
                   file's name without .yaml)
  --range A:B      only frames A .. B-1
  --shard K/N      only frames i with i mod N == K (0 <= K < N), e.g. one task
                   of a cluster job array; combines with --range
  --shard auto     the shard from the cluster scheduler's environment: a
                   Slurm job array (task SLURM_ARRAY_TASK_ID minus
                   SLURM_ARRAY_TASK_MIN, of SLURM_ARRAY_TASK_COUNT) or a
                   Kubernetes Indexed Job (JOB_COMPLETION_INDEX, of --shards N)
  --shards N       the shard count for --shard auto in a Kubernetes Indexed
                   Job (the Job's completions)
  --resume         skip frames whose file is already complete (after an
                   interrupted or killed run: renders exactly the missing ones)
  --raw-video F    also write every frame, in order, as raw RGB24 to file F
                   ('-': standard output), for an encoder to read while the
                   frames render: `... --raw-video - | ffmpeg -f rawvideo
                   -pix_fmt rgb24 -s WxH -r FPS -i - ...` (scripts/encode.sh
                   --raw does this); not with --shard or --resume
  --raw-pix-fmt P  the raw video's pixels: rgb24 (default) or yuv420p,
                   BT.601 limited range as ffmpeg converts RGB, luma the
                   same bytes, chroma the mean of each 2x2 block; converted
                   on the render threads, which spares the encoder the work
  --threads N      worker threads (default: one per core)
  --spp N, --depth N, --precision P, --adaptive, --aa-threshold X,
  --aa-samples N, --no-prune   as for render
  --stats          print the rays traced, as key: value lines on stdout
  --quiet          no progress line

SIGINT or SIGTERM (Ctrl-C): no new frames are started, the frames in flight
are finished if they take less than half a second more (else abandoned),
and the run exits with 128 + the signal's number; run it again with --resume.
A killed run leaves only whole frames; temporaries (frame_NNNN.png.tmp-...)
of dead runs are removed by the next run.
)";

namespace {
// How long frames in flight may take after SIGINT/SIGTERM before the run
// abandons them and exits.
constexpr std::chrono::milliseconds kInterruptGrace{500};
}  // namespace

int run_frames(const Words& words) {
    if (wants_help(words, kFramesHelp)) return 0;
    const Args args = Args::parse(
        "frames", words,
        {{"--out"}, {"--range"}, {"--shard"}, {"--shards"}, {"--resume", false}, {"--threads"}, {"--spp"},
         {"--depth"}, {"--precision"}, {"--no-prune", false}, {"--adaptive", false}, {"--aa-threshold"},
         {"--aa-samples"}, {"--stats", false}, {"--quiet", false}, {"--raw-video"}, {"--raw-pix-fmt"}});
    if (args.positional().size() != 1)
        throw UsageError("expected one MOVIE file, got " + std::to_string(args.positional().size()));
    const std::string file = args.positional()[0];
    if (!is_movie_file(file)) {
        // Unreadable, not YAML, or a scene with mistakes: say what is wrong
        // with it, at its position, rather than only that it is no movie.
        load_scene(file);
        throw UsageError(file + " is not a movie file (a movie file has a 'scene:' key)");
    }
    Movie movie = load_movie(file);
    const int n = movie.frame_count();

    std::vector<int> frames;
    // --shards N: the count for --shard auto in a Kubernetes Indexed Job (issue 10).
    const auto shards = args.has("--shards") ? std::optional(args.integer("--shards", 1, 1, 1'000'000)) : std::nullopt;
    if (shards && !args.has("--shard")) throw UsageError("--shards N goes with --shard auto");
    try {
        frames = select_frames(n, args.has("--range") ? std::optional(parse_range(*args.value("--range")))
                                                      : std::nullopt,
                               args.has("--shard") ? std::optional(parse_shard_option(*args.value("--shard"), shards))
                                                   : std::nullopt);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    try {
        warn_parallel_up(file, check_camera_path(movie));
    } catch (const std::invalid_argument& e) {
        throw InputError(file, e.what());
    }
    RenderSettings settings = movie.scene.render;
    apply_quality_flags(args, settings);
    const int threads = args.integer("--threads", 0, 0, 1024);

    namespace fs = std::filesystem;
    const fs::path out =
        args.value("--out").value_or((fs::path("output") / fs::path(file).stem()).string());
    prepare_output_folder(out.string());
    if (const int removed = remove_stale_temporaries(out.string()))
        std::cerr << "firsthit: removed " << removed << " temporary file(s) left by an interrupted run in "
                  << out.string() << "\n";

    // The stream is the movie's frames in order: all of them, or a range.
    std::optional<RawVideoWriter> raw_video;
    if (const auto raw = args.value("--raw-video")) {
        if (args.has("--shard") || args.has("--resume"))
            throw UsageError("--raw-video streams whole runs of frames: not with --shard or --resume");
        if (*raw == "-" && args.has("--stats"))
            throw UsageError("--raw-video - writes frames to standard output: not with --stats");
        RawPixelFormat format = RawPixelFormat::rgb24;
        try {
            if (const auto name = args.value("--raw-pix-fmt")) format = parse_raw_pixel_format(*name);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--raw-pix-fmt: ") + e.what());
        }
        raw_video.emplace(*raw, 8, format);
    } else if (args.has("--raw-pix-fmt")) {
        throw UsageError("--raw-pix-fmt goes with --raw-video");
    }
    if (args.has("--resume"))
        std::erase_if(frames, [&](int i) { return is_complete_png((out / frame_file_name(i, n)).string()); });

    Progress progress(int(frames.size()), !args.has("--quiet") && isatty(STDERR_FILENO));
    // Frames are written under a shared lock; the interrupt watch takes it
    // alone before ending the process, so no file is half written then.
    std::shared_mutex write_mutex;
    std::atomic<bool> finished{false};
    const InterruptWatch watch(kInterruptGrace, [&](int sig) {
        std::unique_lock lock(write_mutex);
        if (finished) return;  // the run ended meanwhile: it reports itself
        progress.finish();
        std::cerr << "firsthit: interrupted after " << progress.done() << " of " << frames.size()
                  << " frames (frames in flight abandoned); run again with --resume to render the rest\n";
        std::_Exit(128 + sig);
    });
    ThreadPool pool(threads);
    std::mutex counts_mutex;
    RayCounts counts;
    pool.parallel_for(int(frames.size()), [&](int task, int) {
        if (interrupted()) return;
        const int i = frames[size_t(task)];
        FrameResult r;
        try {
            r = render_frame(movie.scene, camera_at(movie, i), settings, movie.scene.effects, nullptr);
            {
                std::shared_lock lock(write_mutex);
                write_png((out / frame_file_name(i, n)).string(), r.image);
            }
            if (raw_video) raw_video->put(task, std::move(r.image));
        } catch (const std::exception& e) {
            if (raw_video) raw_video->fail(e.what());  // frames after this one wait for it
            throw;
        }
        {
            std::lock_guard lock(counts_mutex);
            counts += r.counts;
        }
        progress.frame_done();
    });
    {
        std::unique_lock lock(write_mutex);
        finished = true;
    }
    progress.finish();
    if (interrupted()) {
        std::cerr << "firsthit: interrupted after " << progress.done() << " of " << frames.size()
                  << " frames; run again with --resume to render the rest\n";
        return 128 + interrupt_signal();
    }
    std::cerr << "rendered " << frames.size() << " frames in " << progress.seconds() << " s ("
              << progress.fps() << " frames/s) into " << out.string() << "\n";
    if (args.has("--stats")) {
        std::cout << "frames: " << frames.size() << "\n"
                  << "seconds: " << progress.seconds() << "\n"
                  << "frames_per_second: " << progress.fps() << "\n";
        print_counts(std::cout, counts);
    }
    return 0;
}

}  // namespace fh
