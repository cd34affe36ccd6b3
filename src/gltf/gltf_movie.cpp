#include "gltf/gltf_movie.h"

#include <cmath>
#include <cstdio>

#include "gltf/gltf_cameras_lights.h"
#include "gltf/gltf_loader.h"
#include "text/closest_match.h"
#include "text/input_error.h"

namespace fh {

namespace {

// An index given as a whole number below `count`, or -1.
int as_index(const std::string& text, size_t count) {
    if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos) return -1;
    const long v = std::stol(text);
    return size_t(v) < count ? int(v) : -1;
}

template <typename Named>
int pick(const std::vector<Named>& items, const std::string& which, const char* what, const std::string& file) {
    std::vector<std::string> names;
    for (size_t i = 0; i < items.size(); ++i) {
        if (items[i].name == which) return int(i);
        names.push_back(items[i].name);
    }
    if (const int i = as_index(which, items.size()); i >= 0) return i;
    const std::string near = closest_match(which, names);
    std::string list;
    for (size_t i = 0; i < names.size() && i < 8; ++i) list += (i ? ", " : "") + std::to_string(i) + " '" + names[i] + "'";
    throw UsageError("no " + std::string(what) + " '" + which + "' in " + file +
                     (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                     (names.empty() ? std::string(" (it has none)") : "; it has " + list));
}

}  // namespace

std::vector<NodeChannel> chosen_channels(const std::vector<NodeAnimation>& animations, const std::string& which,
                                         const std::string& file) {
    std::vector<NodeChannel> out;
    if (which == "all") {
        for (const NodeAnimation& a : animations) out.insert(out.end(), a.channels.begin(), a.channels.end());
        return out;
    }
    return animations[size_t(pick(animations, which, "animation", file))].channels;
}

GltfScene gltf_scene(const std::string& path, double exposure) { return gltf_scene(load_gltf(path, exposure), exposure); }

GltfScene gltf_scene(GltfFile file, double exposure) {
    GltfScene out;
    out.warnings = std::move(file.warnings);
    const bool has_lights = !file.scene.directional_lights.empty() || !file.scene.spot_lights.empty();
    out.animations = add_gltf(out.scene, std::move(file), "model", Transform{});
    if (out.scene.cameras.empty()) add_default_camera(out.scene);
    add_default_lights(out.scene, out.scene.cameras.front(), exposure, !has_lights);
    return out;
}

Movie load_gltf_movie(const GltfMovieRequest& request) {
    return gltf_movie(gltf_scene(request.file, request.exposure), request);
}

Movie gltf_movie(GltfScene g, const GltfMovieRequest& request) {
    Movie movie;
    movie.scene = std::move(g.scene);
    movie.warnings = std::move(g.warnings);
    const std::vector<NodeAnimation>& animations = g.animations;
    const int camera = request.camera ? pick(movie.scene.cameras, *request.camera, "camera", request.file) : 0;
    movie.camera = movie.scene.cameras[size_t(camera)];
    movie.node_channels = chosen_channels(animations, request.animation.value_or("all"), request.file);
    // As long as the longest channel: its last key falls on a frame.
    double end = 0;
    for (const NodeChannel& c : movie.node_channels) end = std::max(end, c.sampler.end());
    movie.fps = request.fps;
    const double frames = std::floor(end * request.fps + 1e-9) + 1;
    if (frames > 1'000'000) {
        char count[32];  // up to 1e308: printed as a double, never through a long
        std::snprintf(count, sizeof count, "%.4g", frames);
        throw InputError(request.file, std::string(count) + " frames at this --fps (the limit is 1,000,000)");
    }
    movie.seconds = frames / request.fps;
    return movie;
}

}  // namespace fh
