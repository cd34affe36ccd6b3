// firsthit render FILE: one frame to PNG.
#include <filesystem>
#include <iostream>

#include "cli/commands.h"
#include "cli/job.h"
#include "cli/stats_output.h"
#include "pipeline/frame_pipeline.h"

namespace fh {

const char* const kRenderHelp =
    R"(usage: firsthit render FILE [options]

Renders one frame of a scene or movie file to a PNG.

  FILE               a scene file, or a movie file (which names its scene)
  --camera NAME      scene files: the camera to render (default: the first listed)
  --frame N          movie files: the frame index, 0 .. frames-1 (default 0)
  --spp N            samples per pixel (default: the file's, else 1)
  --depth N          maximum chain of reflection rays (default: the file's, else 5)
  --precision P      float or double: the tracer's scalar type (default double)
  --adaptive         adaptive anti-aliasing: pixels that differ from a
                     neighbour by more than --aa-threshold (0..255, default 8)
                     are rendered again with --aa-samples samples (default 16)
  --threads N        worker threads (default: one per core)
  --no-prune         debug: simulate every effect asked for, even those the
                     effect plan proves cannot change a pixel (same image, slower)
  --stats            print the effect plan (what is simulated and why the
                     rest is not) and the rays traced by kind, as key: value
                     lines on stdout
  -o, --output OUT   the PNG to write (default: FILE's name with .png, in the
                     current folder; for a movie, NAME_frameNNNN.png)
)";

namespace {
std::string default_output(const Job& job) {
    std::string stem = std::filesystem::path(job.file).stem().string();
    if (job.frame >= 0) {
        std::string n = std::to_string(job.frame);
        stem += "_frame" + std::string(n.size() < 4 ? 4 - n.size() : 0, '0') + n;
    }
    return stem + ".png";
}
}  // namespace

int run_render(const Words& words) {
    if (wants_help(words, kRenderHelp)) return 0;
    auto spec = job_flags();
    spec.insert(spec.end(), {{"--threads"}, {"--stats", false}, {"-o"}, {"--output"}});
    const Args args = Args::parse("render", words, spec);
    const Job job = job_from_args(args);
    const int threads = args.integer("--threads", 0, 0, 1024);
    std::string out = args.value("-o").value_or(args.value("--output").value_or(""));
    if (out.empty()) out = default_output(job);
    const StillResult still = render_to_file(job, out, threads);
    const FrameResult& r = still.frame;
    if (args.has("--stats")) {
        std::cout << "file: " << job.file << "\n";
        if (job.frame >= 0) std::cout << "frame: " << job.frame << "\n";
        std::cout << "camera: " << job.camera.name << "\n"
                  << "width: " << job.camera.width << "\n"
                  << "height: " << job.camera.height << "\n"
                  << "samples_per_pixel: " << job.settings().samples_per_pixel << "\n"
                  << "precision: " << precision_name(job.settings().precision) << "\n"
                  << "threads: " << still.threads << "\n";
        std::cout << "triangles: " << job.scene().triangles.size() << "\n"
                  << "degenerate_triangles_dropped: " << job.scene().degenerate_mesh_triangles << "\n";
        print_plan(std::cout, r.plan);
        print_counts(std::cout, r.counts);
        std::cout << "render_ms: " << r.render_ms << "\n"
                  << "output: " << out << "\n";
    }
    return 0;
}

}  // namespace fh
