#include "cli/job.h"

#include <cstdlib>
#include <iostream>

#include "anim/movie.h"
#include "io/input_error.h"
#include "io/movie_loader.h"
#include "io/scene_loader.h"

namespace fh {

std::vector<FlagSpec> job_flags() {
    return {{"--frame"}, {"--camera"}, {"--spp"}, {"--depth"}, {"--precision"}, {"--no-prune", false},
            {"--adaptive", false}, {"--aa-threshold"}, {"--aa-samples"}};
}

void apply_quality_flags(const Args& args, RenderSettings& s) {
    s.samples_per_pixel =
        args.integer("--spp", s.samples_per_pixel, 1, Limits::max_samples_per_pixel);
    s.max_depth = args.integer("--depth", s.max_depth, 0, Limits::max_depth);
    s.prune = !args.has("--no-prune");
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
        if (*p == "float") s.precision = Precision::single;
        else if (*p == "double") s.precision = Precision::dual;
        else throw UsageError("--precision must be 'float' or 'double', got '" + *p + "'");
    }
}

namespace {

std::string frame_list(const std::vector<int>& frames) {
    std::string s;
    for (size_t i = 0; i < frames.size() && i < 10; ++i) s += (i ? ", " : "") + std::to_string(frames[i]);
    if (frames.size() > 10) s += ", ... (" + std::to_string(frames.size()) + " frames)";
    return s;
}

}  // namespace

void warn_parallel_up(const std::string& file, const std::vector<int>& frames) {
    if (frames.empty()) return;
    std::cerr << file << ": warning: view direction parallel to 'up' at frame(s) "
              << frame_list(frames) << "; using the fallback up axis\n";
}

RenderJob load_job(const Args& args) {
    if (args.positional().size() != 1)
        throw UsageError("expected one FILE (a scene or movie file), got " +
                         std::to_string(args.positional().size()));
    RenderJob job;
    job.file = args.positional()[0];
    if (is_movie_file(job.file)) {
        if (args.has("--camera"))
            throw UsageError("--camera applies to scene files; " + job.file +
                             " is a movie (its camera is set in the file)");
        Movie movie = load_movie(job.file);
        const int n = movie.frame_count();
        job.frame = args.integer("--frame", 0, 0, n - 1);
        try {
            warn_parallel_up(job.file, check_camera_path(movie));
        } catch (const std::invalid_argument& e) {
            throw InputError(job.file, e.what());
        }
        job.camera = camera_at(movie, job.frame);
        job.scene = std::move(movie.scene);
    } else {
        if (args.has("--frame"))
            throw UsageError("--frame applies to movie files; " + job.file + " is a scene");
        job.scene = load_scene(job.file);
        if (const auto name = args.value("--camera")) {
            const Camera* cam = job.scene.find_camera(*name);
            if (!cam) {
                std::vector<std::string> names;
                for (const auto& c : job.scene.cameras) names.push_back(c.name);
                const std::string near = closest_match(*name, names);
                throw UsageError("no camera '" + *name + "' in " + job.file +
                                 (near.empty() ? "" : " (did you mean '" + near + "'?)"));
            }
            job.camera = *cam;
        } else {
            job.camera = job.scene.cameras.front();
        }
    }
    job.settings = job.scene.render;
    job.effects = job.scene.effects;
    apply_quality_flags(args, job.settings);
    return job;
}

}  // namespace fh
