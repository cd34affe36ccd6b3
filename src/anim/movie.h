// A movie (report section 10): a scene, one of its cameras, the lights that are
// on, and paths that move the camera frame by frame.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "anim/path.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace fh {

struct Movie {
    Scene scene;               // the movie's lights already applied
    RenderSettings settings;   // the scene file's, with the movie's `render:` and `effects:` on top
    Camera camera; // the base camera; animated properties replace its values
    double fps = 30;
    double seconds = 10;
    std::optional<Path> view_point;
    std::optional<Path> look_at;
    std::optional<Path> up;

    int frame_count() const;  // round(fps * seconds)
};

// The camera at frame i (0 <= i < frame_count()).
Camera camera_at(const Movie& movie, int frame);

// Checks every frame's camera before rendering starts. A zero-length (or
// non-finite) view direction at some frame is an error naming that frame
// (std::invalid_argument); frames where the view direction is parallel to up
// (the camera falls back to the documented rule of camera_basis) are returned
// so the caller can warn about them.
std::vector<int> check_camera_path(const Movie& movie);

}  // namespace fh
