// The viewer's state without any window: which file, frame and camera are
// shown, what P, Left/Right, Home/End and playback do to them, the saved
// file's name and the window title. Header-only so the unit tests
// (tests/view/test_view_state.cpp) use it without linking GLFW.
//
// P's rule:
//   - scene file: the next camera of the scene (in file order, wrapping) whose
//     projection differs from the shown one; if every camera has the same
//     projection, the next camera. With one camera P does nothing.
//   - movie file: the movie's camera keeps its path (view point, look_at and
//     up at every frame) and its other fields; only the projection flips
//     (perspective <-> orthographic). Its name gets "-orthographic" or
//     "-perspective" appended while it differs from the movie's.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "anim/movie.h"
#include "scene/scene.h"

namespace fh::view {

inline const char* projection_name(Projection p) {
    return p == Projection::orthographic ? "orthographic" : "perspective";
}

inline Projection other(Projection p) {
    return p == Projection::orthographic ? Projection::perspective : Projection::orthographic;
}

class ViewState {
public:
    // A scene file, showing cameras[camera_index].
    ViewState(std::string file, const Scene& scene, int camera_index)
        : file_(std::move(file)), scene_(&scene), camera_index_(camera_index) {}
    // A movie file, showing `frame`.
    ViewState(std::string file, const Movie& movie, int frame)
        : file_(std::move(file)), movie_(&movie), frame_(frame),
          projection_(movie.camera.projection) {}

    bool is_movie() const { return movie_ != nullptr; }
    int frame() const { return frame_; }  // 0 for a scene
    int frame_count() const { return movie_ ? movie_->frame_count() : 1; }
    double fps() const { return movie_ ? movie_->fps : 0; }
    const std::string& file() const { return file_; }

    // The camera to render for what is shown.
    Camera camera() const {
        if (!movie_) return scene_->cameras[size_t(camera_index_)];
        Camera c = camera_at(*movie_, frame_);
        if (projection_ != movie_->camera.projection) {
            c.projection = projection_;
            c.name += std::string("-") + projection_name(projection_);
        }
        return c;
    }

    // P. True if the camera changed.
    bool switch_camera() {
        if (movie_) {
            projection_ = other(projection_);
            return true;
        }
        const auto& cams = scene_->cameras;
        const int n = int(cams.size());
        if (n < 2) return false;
        const Projection now = cams[size_t(camera_index_)].projection;
        for (int k = 1; k < n; ++k) {
            const int i = (camera_index_ + k) % n;
            if (cams[size_t(i)].projection != now) {
                camera_index_ = i;
                return true;
            }
        }
        camera_index_ = (camera_index_ + 1) % n;
        return true;
    }

    // Left/Right (delta -1/+1), clamped to the movie. True if the frame changed.
    bool step(int delta) { return set_frame(frame_ + delta); }
    bool home() { return set_frame(0); }
    bool end() { return set_frame(frame_count() - 1); }
    bool set_frame(int f) {
        f = std::clamp(f, 0, frame_count() - 1);
        if (f == frame_) return false;
        frame_ = f;
        return true;
    }

    // view_<stem>_frameNNNN_<camera>.png (no _frameNNNN for a scene).
    std::string save_name() const {
        std::string s = "view_" + std::filesystem::path(file_).stem().string();
        if (movie_) {
            char buf[32];
            std::snprintf(buf, sizeof buf, "_frame%04d", frame_);
            s += buf;
        }
        return s + "_" + camera().name + ".png";
    }

    // "firsthit view: FILE | frame F/N | CAMERA (projection) | W x H | MS ms".
    std::string title(int shown_width, int shown_height, double ms, bool playing) const {
        const Camera c = camera();
        std::string t = "firsthit view: " + std::filesystem::path(file_).filename().string();
        if (movie_)
            t += " | frame " + std::to_string(frame_) + "/" + std::to_string(frame_count() - 1);
        t += " | " + c.name;
        if (c.name != projection_name(c.projection))
            t += std::string(" (") + projection_name(c.projection) + ")";
        t += " | " + std::to_string(shown_width) + "x" + std::to_string(shown_height);
        if (ms >= 0) t += " | " + std::to_string(int(std::lround(ms))) + " ms";
        if (playing) t += " | playing";
        return t;
    }

private:
    std::string file_;
    const Scene* scene_ = nullptr;
    const Movie* movie_ = nullptr;
    int camera_index_ = 0;
    int frame_ = 0;
    Projection projection_ = Projection::perspective;
};

// A camera showing the same view at 1/divisor of the resolution (the image
// plane is 10 units tall whatever the size, so only the pixel count changes).
inline Camera reduced(Camera c, int divisor) {
    if (divisor <= 1) return c;
    c.width = std::max(1, c.width / divisor);
    c.height = std::max(1, c.height / divisor);
    return c;
}

// Playback never lags the clock: the frame shown at `elapsed` seconds after
// starting at `start_frame` is picked from the time, looping at the end, and
// frames the renderer cannot keep up with are skipped.
inline int frame_at(int start_frame, double elapsed_seconds, double fps, int frame_count) {
    if (frame_count <= 0) return 0;
    const long long advanced = (long long)std::floor(std::max(0.0, elapsed_seconds) * fps);
    return int((start_frame + advanced) % frame_count);
}

// The resolution divisor during playback (1, 2, 4, ... up to max_divisor):
// halve the resolution when a frame took longer than the frame period, double
// it again when frames take well under a quarter of it (a frame at twice the
// resolution costs about four times as much).
inline int adapt_divisor(int divisor, double frame_ms, double fps, int max_divisor = 16) {
    const double budget_ms = 1000.0 / fps;
    if (frame_ms > budget_ms && divisor < max_divisor) return divisor * 2;
    if (frame_ms < 0.2 * budget_ms && divisor > 1) return divisor / 2;
    return divisor;
}

}  // namespace fh::view
