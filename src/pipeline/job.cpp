#include "pipeline/job.h"

#include <algorithm>
#include <cmath>

#include "gltf/gltf_loader.h"
#include "gltf/gltf_movie.h"
#include "text/closest_match.h"
#include "text/input_error.h"
#include "yaml/movie_loader.h"
#include "text/parse_int.h"
#include "yaml/scene_loader.h"

namespace fh {

namespace {

std::string frame_list(const std::vector<int>& frames) {
    std::string s;
    for (size_t i = 0; i < frames.size() && i < 10; ++i) s += (i ? ", " : "") + std::to_string(frames[i]);
    if (frames.size() > 10) s += ", ... (" + std::to_string(frames.size()) + " frames)";
    return s;
}

int camera_index(const Scene& scene, const std::string& name, const std::string& file) {
    std::vector<std::string> names;
    for (const auto& c : scene.cameras) names.push_back(c.name);
    for (size_t i = 0; i < names.size(); ++i)
        if (names[i] == name) return int(i);
    throw UsageError("no camera '" + name + "' in " + file + name_hint(name, names, "its cameras"));
}

}  // namespace

std::vector<std::string> check_movie_cameras(const std::string& file, const Movie& movie) {
    std::vector<int> parallel;
    try {
        parallel = check_animations(movie);
    } catch (const AnimationError& e) {
        throw InputError(file, e.line, e.column, e.what());
    }
    if (parallel.empty()) return {};
    return {file + ": warning: view direction parallel to 'up' at frame(s) " + frame_list(parallel) +
            "; using the fallback up axis"};
}

void resize_camera(Camera& camera, const SizeOverride& size) {
    auto side = [&](int file_side) {
        const double v = std::max(1.0, std::round(file_side * size.scale));
        if (v > Limits::max_image_side)
            throw UsageError("--scale makes a side of " + std::to_string(long(v)) + " pixels; at most " +
                             std::to_string(Limits::max_image_side));
        return int(v);
    };
    if (size.width > 0 && size.height > 0) {
        camera.width = size.width;
        camera.height = size.height;
    } else if (size.scale > 0) {
        camera.width = side(camera.width);
        camera.height = side(camera.height);
    }
}

Job load_job(const JobRequest& request) {
    Job job;
    job.file = request.file;
    const bool gltf = is_gltf_file(job.file);
    if (!gltf && (request.animation || request.fps || request.exposure))
        throw UsageError(std::string(request.animation ? "--animation" : request.fps ? "--fps" : "--exposure") +
                         " applies to glTF files (.gltf, .glb); " + job.file + " is not one");
    job.is_movie_file = gltf || is_movie_file(job.file);
    if (job.is_movie_file) {
        if (request.camera && !gltf)
            throw UsageError("--camera applies to scene files; " + job.file + " is a movie (" +
                             request.movie_camera_note + ")");
        job.movie = gltf ? load_gltf_movie({job.file, request.camera, request.animation, request.fps.value_or(30),
                                            request.exposure.value_or(1)})
                         : load_movie(job.file);
        job.frame = request.frame ? parse_int(*request.frame, "--frame", 0, job.movie.frame_count() - 1) : 0;
        resize_camera(job.movie.camera, request.size);
        job.warnings = job.movie.warnings;
        if (request.check_cameras)
            for (std::string& w : check_movie_cameras(job.file, job.movie)) job.warnings.push_back(std::move(w));
        job.camera = camera_at(job.movie, job.frame);
        if (job.movie.scene_changes()) {
            job.frame_scene = job.movie.scene;
            scene_at(job.movie, job.frame, *job.frame_scene);
        }
        return job;
    }
    if (request.frame) throw UsageError("--frame applies to movie files; " + job.file + " is a scene");
    SceneFile scene_file = load_scene(job.file);
    job.movie.scene = std::move(scene_file.scene);
    job.movie.settings = scene_file.settings;
    job.warnings = std::move(scene_file.warnings);
    for (Camera& c : job.movie.scene.cameras) resize_camera(c, request.size);
    if (request.camera) job.camera_index = camera_index(job.movie.scene, *request.camera, job.file);
    job.camera = job.movie.scene.cameras[size_t(job.camera_index)];
    job.movie.camera = job.camera;
    job.movie.fps = 1;
    job.movie.seconds = 1;
    return job;
}

}  // namespace fh
