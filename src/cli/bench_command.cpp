// firsthit bench FILE: how fast one frame renders (no file writing).
#include <algorithm>
#include <chrono>
#include <iostream>

#include "cli/commands.h"
#include "cli/job.h"
#include "cli/stats_output.h"
#include "pipeline/frame_pipeline.h"

namespace fh {

int run_bench(const Args& args) {
    const auto load_start = std::chrono::steady_clock::now();
    const Job job = job_from_args(args);
    const double load_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - load_start).count();
    const int runs = args.integer("--runs", 7, 1, 10000);
    const FrameTimings timings = time_frame(job, runs, args.integer("--threads", 0, 0, 1024));
    const std::vector<double>& ms = timings.ms;
    const FrameResult& r = timings.last;
    const double ms_median = median(ms);
    const auto [ms_min, ms_max] = std::minmax_element(ms.begin(), ms.end());
    std::cout << "file: " << job.file << "\n";
    if (job.frame >= 0) std::cout << "frame: " << job.frame << "\n";
    std::cout << "width: " << job.camera.width << "\n"
              << "height: " << job.camera.height << "\n"
              << "precision: " << precision_name(job.settings().precision) << "\n"
              << "threads: " << timings.threads << "\n"
              << "runs: " << runs << "\n"
              << "load_ms: " << load_ms << "\n"
              << "prepare_ms: " << timings.prepare_ms << "\n"
              << "build_ms: " << timings.bvh_build_ms << "\n"
              << "bvh_nodes: " << timings.bvh_nodes << "\n"
              << "instances: " << timings.instances << "\n";
    if (timings.frame_update_ms >= 0) std::cout << "frame_update_ms: " << timings.frame_update_ms << "\n";
    std::cout
              << "ms_per_frame: " << ms_median << "\n"
              << "ms_min: " << *ms_min << "\n"
              << "ms_max: " << *ms_max << "\n"
              << "rays_per_second: " << double(r.counts.total()) / (ms_median / 1000.0) << "\n"
              << "rays_per_second.primary: " << double(r.counts.primary) / (ms_median / 1000.0) << "\n"
              << "rays_per_second.shadow: " << double(r.counts.shadow) / (ms_median / 1000.0) << "\n"
              << "rays_per_second.reflection: " << double(r.counts.reflection) / (ms_median / 1000.0)
              << "\n";
    print_plan(std::cout, r.plan);
    print_counts(std::cout, r.counts);
    return 0;
}

}  // namespace fh
