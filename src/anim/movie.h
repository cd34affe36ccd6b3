// A movie (report section 10): a scene, one of its cameras, the lights that
// are on, and paths that change properties of the camera, the lights, the
// named surfaces and the materials frame by frame (anim/property.h). Every
// frame is a pure function of its index: any subset of frames equals the
// same frames of a full run.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "anim/node_channel.h"
#include "anim/path.h"
#include "anim/property.h"
#include "render/prepared_scene.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace fh {

// One animated property. line, column: where the file names it (0: unknown).
struct Animation {
    Target target;
    Path path;
    int line = 0;
    int column = 0;
};

struct Movie {
    Scene scene;               // the movie's lights already applied
    RenderSettings settings;   // the scene file's, with the movie's `render:` and `effects:` on top
    Camera camera; // the base camera; animated properties replace its values
    double fps = 30;
    double seconds = 10;
    std::vector<Animation> animations;
    // A glTF file's animations, on the movie's clock (frame i at i / fps
    // seconds): the nodes they drive, and what hangs on those.
    std::vector<NodeChannel> node_channels;
    std::vector<std::string> warnings;  // the scene file's (yaml/scene_loader.h)

    int frame_count() const;  // round(fps * seconds)

    // Adds (or replaces) the camera property's path: tests and tools.
    void animate_camera(Property property, Path path);
    // Some animated property belongs to the scene (not only the camera).
    bool scene_changes() const;
    // What the animated properties move: the world's own primitives (their
    // BVH is refitted per frame), instances (their top BVH), or nothing.
    ShapeChanges shape_changes() const;
};

// The value of a target at frame i: its path's, or the file's when no path
// animates it.
dvec3 value_at(const Movie& movie, const Target& target, int frame);

// The camera at frame i (0 <= i < frame_count()).
Camera camera_at(const Movie& movie, int frame);

// `scene` -- a copy of movie.scene, perhaps holding another frame's values --
// set to frame i: every animated property of the scene written, moved
// surfaces placed anew. What no path animates is left as it is.
void scene_at(const Movie& movie, int frame, Scene& scene);

// A value a path gives that its property does not allow.
struct AnimationError : std::invalid_argument {
    AnimationError(const std::string& what, int line_, int column_)
        : std::invalid_argument(what), line(line_), column(column_) {}
    int line, column;
};

// Checks every frame's values before rendering starts: the first value a
// property does not allow (a radius <= 0, an intensity < 0, a zero
// direction, NaN, ...) throws AnimationError naming the path, the value and
// the frame. A zero-length (or non-finite) view direction at some frame is
// one too. Frames where the view direction is parallel to up (the camera
// falls back to the documented rule of camera_basis) are returned so the
// caller can warn about them.
std::vector<int> check_animations(const Movie& movie);

}  // namespace fh
