// A glTF file as firsthit renders it on its own (`firsthit render|frames|
// bench|view|export MODEL.glb`): its scene, turned z-up, with a default
// camera and lights where it has none (gltf/gltf_cameras_lights.h), and its
// animations as a movie -- frame i at i / fps seconds, as long as the
// longest animation chosen.
#pragma once

#include <optional>
#include <string>

#include "anim/movie.h"
#include "gltf/gltf_loader.h"

namespace fh {

struct GltfMovieRequest {
    std::string file;
    std::optional<std::string> camera;     // a camera's name or index (default: the first; none: "default")
    std::optional<std::string> animation;  // an animation's name or index, or "all" (default)
    double fps = 30;
    double exposure = 1;
};

// A glTF file as a scene of its own: placed z-up, with a default camera
// where it has none, a key light (from behind its first camera's upper
// left) where it has no light, and an ambient light (gltf/gltf_cameras_lights.h).
struct GltfScene {
    Scene scene;
    std::vector<NodeAnimation> animations;
    std::vector<std::string> warnings;
};
GltfScene gltf_scene(const std::string& path, double exposure = 1);
// The same for a file already read (with that exposure).
GltfScene gltf_scene(GltfFile file, double exposure = 1);

// UsageError for a camera or animation the file does not have (with the
// closest name); InputError for a bad file.
Movie load_gltf_movie(const GltfMovieRequest& request);
// The same for a scene already made of the file (request.file names it; its
// exposure is the scene's).
Movie gltf_movie(GltfScene scene, const GltfMovieRequest& request);

// The channels of the animations `which` names among `animations` ("all",
// a name or an index); UsageError naming the file otherwise.
std::vector<NodeChannel> chosen_channels(const std::vector<NodeAnimation>& animations, const std::string& which,
                                         const std::string& file);

}  // namespace fh
