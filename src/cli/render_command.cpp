// firsthit render FILE: one frame to an image file (or standard output).
#include <filesystem>
#include <iostream>

#include <unistd.h>

#include "cli/commands.h"
#include "cli/human.h"
#include "cli/job.h"
#include "cli/stats_output.h"
#include "files/atomic_file.h"
#include "files/input_files.h"
#include "images/image_writer.h"
#include "text/input_error.h"
#include "pipeline/frame_pipeline.h"

namespace fh {

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

int run_render(const Args& args) {
    one_file(args);
    if (args.value("--output") == "") throw UsageError("-o needs a file name (or '-' for standard output)");
    std::string out = args.value("--output").value_or("");
    if (out == "-") {
        if (args.has("--stats")) throw UsageError("-o - writes the image to standard output: not with --stats");
        if (isatty(STDOUT_FILENO))
            throw UsageError("-o - writes PNG bytes to standard output, which is a terminal; redirect it "
                             "(> out.png) or pipe it");
    }
    if (!out.empty() && out != "-") check_output_file(out);  // a bad place or name before loading anything
    if (!out.empty()) image_format_of(out);
    const Job job = job_from_args(args);
    const int threads = args.integer("--threads", 0, 0, 1024);
    if (out.empty()) out = default_output(job);
    if (out != "-") check_not_an_input(out);  // a texture the scene has just read, say
    const StillResult still = render_to_file(job, out, threads);
    const FrameResult& r = still.frame;
    if (!args.has("--quiet"))
        std::cerr << "wrote " << (out == "-" ? std::string("PNG to standard output") : out) << " ("
                  << job.camera.width << "x" << job.camera.height << ", 1 frame in " << human_duration(r.render_ms / 1000)
                  << ")\n";
    if (args.has("--stats")) {
        std::cout << "file: " << job.file << "\n";
        if (job.frame >= 0) std::cout << "frame: " << job.frame << "\n";
        std::cout << "camera: " << job.camera.name << "\n"
                  << "width: " << job.camera.width << "\n"
                  << "height: " << job.camera.height << "\n"
                  << "precision: " << precision_name(job.settings().precision) << "\n"
                  << "threads: " << still.threads << "\n";
        print_sampling(std::cout, job.settings(), r);
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
