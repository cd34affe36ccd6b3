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
#include "cli/human.h"
#include "cli/stats_output.h"
#include "text/input_error.h"
#include "yaml/movie_loader.h"
#include "yaml/scene_loader.h"
#include "text/parse_int.h"
#include "pipeline/frame_files.h"
#include "pipeline/frame_pipeline.h"
#include "pipeline/job.h"

namespace fh {

namespace {

// The progress line, and the words for an interrupted run.
class FramesProgress : public FramesObserver {
public:
    FramesProgress(std::string folder, bool show, bool show_messages)
        : folder_(std::move(folder)), show_(show), show_messages_(show_messages) {}

    void removed_temporaries(int count) override {
        if (show_messages_)
            std::cerr << "firsthit: removed " << count << " temporary file(s) left by an interrupted run in "
                      << folder_ << "\n";
    }
    void removed_old_frames(int count) override {
        if (show_messages_)
            std::cerr << "firsthit: --clean removed " << plural(count, "old frame") << " in " << folder_ << "\n";
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
    bool show_, show_messages_;
    std::optional<Progress> progress_;
};

// --frame, --range and --shard (or --shard auto) as the frames of an n-frame movie.
std::vector<int> selected_frames(const Args& args, int n) {
    // --shards N: the count for --shard auto in a Kubernetes Indexed Job.
    const auto shards = args.has("--shards") ? std::optional(args.integer("--shards", 1, 1, 1'000'000)) : std::nullopt;
    if (shards && !args.has("--shard")) throw UsageError("--shards N goes with --shard auto");
    try {
        const auto range = args.value("--range");
        const auto shard_text = args.value("--shard");
        const auto shard = shard_text ? std::optional(parse_shard_option(*shard_text, shards)) : std::nullopt;
        if (const auto frame = args.value("--frame")) {
            if (range) throw UsageError("--frame N is --range N-N: give one of them");
            const int i = parse_int(*frame, "--frame", 0, n - 1);
            return select_frames(n, FrameRange{i, i + 1}, shard);
        }
        return select_frames(n, range ? std::optional(parse_range(*range)) : std::nullopt, shard);
    } catch (const std::invalid_argument& e) {
        const auto range = args.value("--range");
        const std::string what = e.what();
        throw UsageError(range && what.rfind("--range", 0) != 0 ? "--range " + *range + ": " + what : what);
    }
}

}  // namespace

int run_frames(const Args& args) {
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
    what.size = size_from_args(args);
    const Job job = load_job(what);

    FramesRequest request;
    request.frames = selected_frames(args, job.movie.frame_count());
    const bool quiet = args.has("--quiet");
    if (!quiet) print_warnings(job);  // the scene's
    for (const std::string& warning : check_movie_cameras(file, job.movie))
        if (!quiet) std::cerr << warning << "\n";
    RenderSettings settings = job.movie.settings;
    apply_quality_flags(args, settings);
    request.threads = args.integer("--threads", 0, 0, 1024);
    request.files = parse_frame_files(
        args.value("--out").value_or((std::filesystem::path("output") / std::filesystem::path(file).stem()).string()));
    request.movie_file = file;
    request.resume = args.has("--resume");
    request.clean = args.has("--clean");
    if (request.clean && request.resume) throw UsageError("--clean removes the frames --resume would keep: give one");
    if (request.clean && args.has("--shard"))
        throw UsageError("--clean with --shard would remove the frames other shards render: clean once, before");
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

    FramesProgress progress(request.files.folder.string(), !quiet && isatty(STDERR_FILENO), !quiet);
    const FramesSummary run = render_frames(job.movie, settings, request, progress);
    progress.finish();
    if (run.interrupt_signal) {
        std::cerr << "firsthit: interrupted after " << run.rendered << " of " << run.to_render
                  << " frames; run again with --resume to render the rest\n";
        return 128 + run.interrupt_signal;
    }
    const double fps = run.seconds > 0 ? run.rendered / run.seconds : 0;
    if (!quiet)
        std::cerr << "rendered " << plural(run.to_render, "frame") << " in " << human_duration(run.seconds) << " ("
                  << human_number(fps) << " frames/s) into " << request.files.folder.string() << "\n";
    if (args.has("--stats")) {
        std::cout << "frames: " << run.to_render << "\n"
                  << "seconds: " << run.seconds << "\n"
                  << "frames_per_second: " << fps << "\n";
        if (settings.adaptive) std::cout << "refined_pixels: " << run.refined_pixels << "\n";
        print_counts(std::cout, run.counts);
    }
    return 0;
}

}  // namespace fh
