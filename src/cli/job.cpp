#include "cli/job.h"

#include <cstdlib>
#include <iostream>

#include "gltf/gltf_loader.h"
#include "text/input_error.h"

namespace fh {

SizeOverride size_from_args(const Args& args) {
    SizeOverride size;
    if (const auto r = args.value("--resolution")) {
        if (args.has("--scale")) throw UsageError("--resolution and --scale both set the size: give one");
        const size_t x = r->find_first_of("xX");
        if (x == std::string::npos)
            throw UsageError("--resolution takes WIDTHxHEIGHT, e.g. 160x120, got '" + *r + "'");
        size.width = parse_int(r->substr(0, x), "--resolution's width", 1, Limits::max_image_side);
        size.height = parse_int(r->substr(x + 1), "--resolution's height", 1, Limits::max_image_side);
    }
    size.scale = args.number("--scale", 0, 1e-6, Limits::max_image_side);
    return size;
}

void apply_quality_flags(const Args& args, RenderSettings& s) {
    s.samples_per_pixel =
        args.integer("--spp", s.samples_per_pixel, 1, Limits::max_samples_per_pixel);
    s.max_depth = args.integer("--depth", s.max_depth, 0, Limits::max_depth);
    s.prune = !args.has("--no-prune");
    if (args.has("--no-mipmaps")) s.mipmaps = false;
    if (args.has("--adaptive")) s.adaptive = true;
    s.adaptive_samples =
        args.integer("--aa-samples", s.adaptive_samples, 1, Limits::max_samples_per_pixel);
    if (const auto t = args.value("--aa-threshold")) {
        char* end = nullptr;
        const double v = std::strtod(t->c_str(), &end);
        if (t->empty() || *end != '\0' || !(v >= 0 && v <= 255))
            throw UsageError("--aa-threshold must be a number in [0, 255], got '" + *t + "'");
        s.adaptive_threshold = v;
    }
    if (const auto p = args.value("--precision")) {
        if (*p == "float") s.precision = Precision::float32;
        else if (*p == "double") s.precision = Precision::float64;
        else throw UsageError("--precision must be 'float' or 'double', got '" + *p + "'");
    }
}

void print_warnings(const Job& job) {
    for (const std::string& w : job.warnings) std::cerr << w << "\n";
}

const std::string& one_file(const Args& args) {
    if (args.positional().size() != 1)
        throw UsageError("expected one FILE (a scene or movie file), got " +
                         std::to_string(args.positional().size()));
    return args.positional()[0];
}

JobRequest job_request_from_args(const Args& args) {
    one_file(args);
    JobRequest request;
    request.file = args.positional()[0];
    request.camera = args.value("--camera");
    request.frame = args.value("--frame");
    request.size = size_from_args(args);
    request.animation = args.value("--animation");
    if (args.has("--fps")) request.fps = args.number("--fps", 30, 1e-3, 1000);
    if (args.has("--exposure")) request.exposure = args.number("--exposure", 1, 0, kMaxExposure);
    return request;
}

Job job_from_args(const Args& args, const char* movie_camera_note) {
    JobRequest request = job_request_from_args(args);
    if (movie_camera_note) request.movie_camera_note = movie_camera_note;
    Job job = load_job(request);
    if (!args.has("--quiet")) print_warnings(job);
    apply_quality_flags(args, job.movie.settings);
    return job;
}

}  // namespace fh
