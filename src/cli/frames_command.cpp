// firsthit frames MOVIE: every frame of a movie (or a range or shard of them)
// to DIR/frame_NNNN.png. Frames are spread over the pool one per worker: each
// worker renders its frame on its own and encodes the PNG, so PNG encoding
// runs beside rendering instead of stalling it.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <mutex>

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
  --resume         skip frames whose file is already complete
  --threads N      worker threads (default: one per core)
  --spp N, --depth N, --precision P, --no-prune   as for render
  --stats          print the rays traced, as key: value lines on stdout
  --quiet          no progress line
)";

int run_frames(const Words& words) {
    if (wants_help(words, kFramesHelp)) return 0;
    const Args args = Args::parse(
        "frames", words,
        {{"--out"}, {"--range"}, {"--shard"}, {"--resume", false}, {"--threads"}, {"--spp"},
         {"--depth"}, {"--precision"}, {"--no-prune", false}, {"--stats", false}, {"--quiet", false}});
    if (args.positional().size() != 1)
        throw UsageError("expected one MOVIE file, got " + std::to_string(args.positional().size()));
    const std::string file = args.positional()[0];
    if (!is_movie_file(file))
        throw UsageError(file + " is not a movie file (a movie file has a 'scene:' key)");
    Movie movie = load_movie(file);
    const int n = movie.frame_count();

    std::vector<int> frames;
    try {
        frames = select_frames(n, args.has("--range") ? std::optional(parse_range(*args.value("--range")))
                                                      : std::nullopt,
                               args.has("--shard") ? std::optional(parse_shard(*args.value("--shard")))
                                                   : std::nullopt);
        warn_parallel_up(file, check_camera_path(movie));
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    RenderSettings settings = movie.scene.render;
    apply_quality_flags(args, settings);

    namespace fs = std::filesystem;
    const fs::path out =
        args.value("--out").value_or((fs::path("output") / fs::path(file).stem()).string());
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec || !fs::is_directory(out))
        throw std::runtime_error("cannot create output folder " + out.string() + ": " + ec.message());

    if (args.has("--resume"))
        std::erase_if(frames, [&](int i) { return is_complete_png((out / frame_file_name(i, n)).string()); });

    install_interrupt_handlers();
    ThreadPool pool(args.integer("--threads", 0, 0, 1024));
    Progress progress(int(frames.size()), !args.has("--quiet") && isatty(STDERR_FILENO));
    std::mutex counts_mutex;
    RayCounts counts;
    pool.parallel_for(int(frames.size()), [&](int task, int) {
        if (interrupted()) return;
        const int i = frames[size_t(task)];
        const FrameResult r =
            render_frame(movie.scene, camera_at(movie, i), settings, movie.scene.effects, nullptr);
        write_png((out / frame_file_name(i, n)).string(), r.image);
        {
            std::lock_guard lock(counts_mutex);
            counts += r.counts;
        }
        progress.frame_done();
    });
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
