// firsthit frames MOVIE: every frame of a movie (or a range or shard of them)
// to DIR/frame_NNNN.png, through the frame pipeline (pipeline/frame_pipeline.h).
#include <filesystem>
#include <iostream>
#include <optional>

#include <unistd.h>

#include "anim/frame_selection.h"
#include "cli/cluster_shard.h"
#include "cli/commands.h"
#include "cli/job.h"
#include "cli/progress.h"
#include "cli/stats_output.h"
#include "io/input_error.h"
#include "io/movie_loader.h"
#include "io/scene_loader.h"
#include "pipeline/frame_pipeline.h"
#include "pipeline/job.h"

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

// The progress line, and the words for an interrupted run.
class FramesProgress : public FramesObserver {
public:
    FramesProgress(std::string folder, bool show) : folder_(std::move(folder)), show_(show) {}

    void removed_temporaries(int count) override {
        std::cerr << "firsthit: removed " << count << " temporary file(s) left by an interrupted run in "
                  << folder_ << "\n";
    }
    void starting(int frames) override { progress_.emplace(frames, show_); }
    void frame_done(int) override { progress_->frame_done(); }
    void abandoning(int done, int total) override {
        progress_->finish();
        std::cerr << "firsthit: interrupted after " << done << " of " << total
                  << " frames (frames in flight abandoned); run again with --resume to render the rest\n";
    }
    void finish() {
        if (progress_) progress_->finish();
    }

private:
    std::string folder_;
    bool show_;
    std::optional<Progress> progress_;
};

// --range and --shard (or --shard auto) as the frames of an n-frame movie.
std::vector<int> selected_frames(const Args& args, int n) {
    // --shards N: the count for --shard auto in a Kubernetes Indexed Job.
    const auto shards = args.has("--shards") ? std::optional(args.integer("--shards", 1, 1, 1'000'000)) : std::nullopt;
    if (shards && !args.has("--shard")) throw UsageError("--shards N goes with --shard auto");
    try {
        const auto range = args.value("--range");
        const auto shard = args.value("--shard");
        return select_frames(n, range ? std::optional(parse_range(*range)) : std::nullopt,
                             shard ? std::optional(parse_shard_option(*shard, shards)) : std::nullopt);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

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
    JobRequest what;
    what.file = file;
    what.check_cameras = false;  // after the frame flags, as their errors come first
    const Job job = load_job(what);

    FramesRequest request;
    request.frames = selected_frames(args, job.movie.frame_count());
    print_warnings(job);  // the scene's
    for (const std::string& warning : check_movie_cameras(file, job.movie)) std::cerr << warning << "\n";
    RenderSettings settings = job.movie.settings;
    apply_quality_flags(args, settings);
    request.threads = args.integer("--threads", 0, 0, 1024);
    request.folder = args.value("--out").value_or((std::filesystem::path("output") / std::filesystem::path(file).stem()).string());
    request.resume = args.has("--resume");
    if (const auto raw = args.value("--raw-video")) {
        if (args.has("--shard") || args.has("--resume"))
            throw UsageError("--raw-video streams whole runs of frames: not with --shard or --resume");
        if (*raw == "-" && args.has("--stats"))
            throw UsageError("--raw-video - writes frames to standard output: not with --stats");
        try {
            if (const auto name = args.value("--raw-pix-fmt")) request.raw_pixel_format = parse_raw_pixel_format(*name);
        } catch (const std::invalid_argument& e) {
            throw UsageError(std::string("--raw-pix-fmt: ") + e.what());
        }
        request.raw_video = *raw;
    } else if (args.has("--raw-pix-fmt")) {
        throw UsageError("--raw-pix-fmt goes with --raw-video");
    }

    FramesProgress progress(request.folder.string(), !args.has("--quiet") && isatty(STDERR_FILENO));
    const FramesSummary run = render_frames(job.movie, settings, request, progress);
    progress.finish();
    if (run.interrupt_signal) {
        std::cerr << "firsthit: interrupted after " << run.rendered << " of " << run.to_render
                  << " frames; run again with --resume to render the rest\n";
        return 128 + run.interrupt_signal;
    }
    const double fps = run.seconds > 0 ? run.rendered / run.seconds : 0;
    std::cerr << "rendered " << run.to_render << " frames in " << run.seconds << " s (" << fps
              << " frames/s) into " << request.folder.string() << "\n";
    if (args.has("--stats")) {
        std::cout << "frames: " << run.to_render << "\n"
                  << "seconds: " << run.seconds << "\n"
                  << "frames_per_second: " << fps << "\n";
        print_counts(std::cout, run.counts);
    }
    return 0;
}

}  // namespace fh
