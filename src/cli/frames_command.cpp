// firsthit frames MOVIE: every frame of a movie (or a range or shard of them)
// to DIR/frame_NNNN.png, through the frame pipeline (pipeline/frame_pipeline.h).
#include <iostream>
#include <sstream>

#include <unistd.h>

#include "cli/commands.h"
#include "cli/frames_progress.h"
#include "cli/frames_request.h"
#include "cli/human.h"
#include "cli/job.h"
#include "cli/stats_output.h"
#include "files/input_files.h"
#include "gltf/gltf_loader.h"
#include "pipeline/job.h"
#include "text/input_error.h"
#include "yaml/movie_loader.h"
#include "yaml/scene_loader.h"

namespace fh {

namespace {

// The movie's job, or a clear error for a file that is no movie.
Job movie_job(const Args& args) {
    if (args.positional().size() != 1)
        throw UsageError("expected one MOVIE file, got " + std::to_string(args.positional().size()));
    const std::string file = args.positional()[0];
    if (!is_movie_file(file) && !is_gltf_file(file)) {
        // Unreadable, not YAML, or a scene with mistakes: say what is wrong
        // with it, at its position, rather than only that it is no movie.
        load_scene(file);
        throw UsageError(file + " is not a movie file (a movie file has a 'scene:' key)");
    }
    JobRequest what;
    what.file = file;
    what.check_cameras = false;  // after the frame flags, as their errors come first
    what.size = size_from_args(args);
    what.camera = args.value("--camera");
    what.movie_camera_note = "its camera is set in the file";
    what.animation = args.value("--animation");
    if (args.has("--fps")) what.fps = args.number("--fps", 30, 1e-3, 1000);
    if (args.has("--exposure")) what.exposure = args.number("--exposure", 1, 0, kMaxExposure);
    return load_job(what);
}

// What besides the movie file decides the frames' pixels (FramesOrigin::render).
std::string render_description(const Job& job, const RenderSettings& s, const Args& args) {
    std::ostringstream d;
    d << "camera " << job.movie.camera.name << ", " << s.samples_per_pixel
      << (s.samples_per_pixel == 1 ? " sample" : " samples");
    if (s.adaptive) d << ", adaptive " << s.adaptive_threshold << "/" << s.adaptive_samples;
    d << ", depth " << s.max_depth << ", " << precision_name(s.precision);
    if (!s.mipmaps) d << ", no mipmaps";
    if (const auto a = args.value("--animation")) d << ", animation " << *a;
    if (const auto x = args.value("--exposure")) d << ", exposure " << *x;
    return d.str();
}

void print_summary(const Args& args, const FramesSummary& run, const RenderSettings& settings,
                   const std::string& folder) {
    const double fps = run.seconds > 0 ? run.rendered / run.seconds : 0;
    if (!args.has("--quiet"))
        std::cerr << "rendered " << plural(run.to_render, "frame") << " in " << human_duration(run.seconds) << " ("
                  << human_number(fps) << " frames/s) into " << folder << "\n";
    if (!args.has("--stats")) return;
    std::cout << "frames: " << run.to_render << "\n"
              << "seconds: " << run.seconds << "\n"
              << "frames_per_second: " << fps << "\n";
    if (settings.adaptive) std::cout << "refined_pixels: " << run.refined_pixels << "\n";
    print_counts(std::cout, run.counts);
}

}  // namespace

int run_frames(const Args& args) {
    const Job job = movie_job(args);
    const std::string& file = args.positional()[0];
    std::vector<int> frames = selected_frames(args, job.movie.frame_count());
    const bool quiet = args.has("--quiet");
    if (!quiet) print_warnings(job);  // the scene's
    for (const std::string& warning : check_movie_cameras(file, job.movie))
        if (!quiet) std::cerr << warning << "\n";
    RenderSettings settings = job.movie.settings;
    apply_quality_flags(args, settings);
    FramesRequest request = frames_request(args, file, std::move(frames));
    request.render = render_description(job, settings, args);
    if (request.raw_video && *request.raw_video != "-") check_not_an_input(*request.raw_video);

    FramesProgress progress(request.files.folder.string(), !quiet && isatty(STDERR_FILENO), !quiet);
    const FramesSummary run = render_frames(job.movie, settings, request, progress);
    progress.finish();
    if (run.interrupt_signal) {
        std::cerr << "firsthit: interrupted after " << run.rendered << " of " << run.to_render
                  << " frames; run again with --resume to render the rest\n";
        return 128 + run.interrupt_signal;
    }
    print_summary(args, run, settings, request.files.folder.string());
    return 0;
}

}  // namespace fh
