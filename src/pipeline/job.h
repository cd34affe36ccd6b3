// What a command renders: a scene or movie file loaded, its camera picked
// (a scene file's named or first camera; a movie's camera at a frame) and
// its render settings, in one call shared by render, bench, accuracy and view.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "anim/movie.h"

namespace fh {

// A size that replaces the file's (--resolution WxH), or a factor on it
// (--scale F), for every camera of the job: frames rendered at an override
// are still a pure function of their index.
struct SizeOverride {
    int width = 0, height = 0;  // both > 0: this size
    double scale = 0;           // > 0: the file's sides times this, rounded, at least 1
};

struct JobRequest {
    std::string file;
    std::optional<std::string> camera;  // scene files only: a camera's name
    std::optional<std::string> frame;   // movie files only: the frame, as typed (default 0)
    SizeOverride size;
    // glTF files only: which animation(s), frames per second, light exposure.
    std::optional<std::string> animation;
    std::optional<double> fps;
    std::optional<double> exposure;
    // Check the movie's camera at every frame now (check_movie_cameras);
    // `frames` does it itself, after its own flags are checked.
    bool check_cameras = true;
    // Said after "--camera applies to scene files; FILE is a movie (...)".
    std::string movie_camera_note = "its camera is set in the file";
};

struct Job {
    std::string file;
    // The file's scene and settings, and how they change from frame to
    // frame. A scene file loads as a still movie: no paths, the picked
    // camera, one frame.
    Movie movie;
    bool is_movie_file = false;  // a movie file, or a glTF file (its animations make it one)
    int frame = -1;        // movie files: the picked frame; -1 for a scene file
    int camera_index = 0;  // scene files: the picked camera in movie.scene.cameras
    Camera camera;         // the picked camera: the scene's, or the movie's at `frame`
    std::vector<std::string> warnings;  // one line each, for the command to print
    // A movie that animates more than its camera: the scene at `frame`.
    std::optional<Scene> frame_scene;

    const Scene& scene() const { return frame_scene ? *frame_scene : movie.scene; }
    const RenderSettings& settings() const { return movie.settings; }
};

// Loads request.file and picks its camera. Bad files throw InputError; a
// flag that does not fit the file (--camera on a movie, --frame on a scene,
// an unknown camera, a frame out of range) throws UsageError.
Job load_job(const JobRequest& request);

// The camera resized as `size` says; UsageError when a side would pass
// Limits::max_image_side.
void resize_camera(Camera& camera, const SizeOverride& size);

// A movie's paths checked at every frame (check_animations): a value its
// property does not allow, a zero or non-finite view direction, throws
// InputError naming the file, the path's line and the frame; frames where
// the view is parallel to 'up' (the fallback up is used) give one warning
// line.
std::vector<std::string> check_movie_cameras(const std::string& file, const Movie& movie);

}  // namespace fh
