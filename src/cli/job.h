// What the render, bench and accuracy commands share: load FILE (a scene or a
// movie), pick the camera (--camera, or the movie's camera at --frame), and
// apply the quality flags on top of the file's settings.
#pragma once

#include <string>
#include <vector>

#include "cli/args.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace fh {

struct RenderJob {
    std::string file;
    Scene scene;
    Camera camera;
    RenderSettings settings;
    Effects effects;
    int frame = -1;  // -1: a scene, not a movie
};

// The flags load_job reads.
std::vector<FlagSpec> job_flags();

RenderJob load_job(const Args& args);

// --spp, --depth, --precision and --no-prune on top of the file's settings.
void apply_quality_flags(const Args& args, RenderSettings& settings);

// Prints one warning line naming the frames whose camera used the fallback up.
void warn_parallel_up(const std::string& file, const std::vector<int>& frames);

}  // namespace fh
