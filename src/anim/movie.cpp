#include "anim/movie.h"

#include <cmath>
#include <stdexcept>

namespace fh {

int Movie::frame_count() const {
    return static_cast<int>(std::llround(fps * seconds));
}

Camera camera_at(const Movie& movie, int frame) {
    const int n = movie.frame_count();
    Camera cam = movie.camera;
    // view_point first: a Toward look_at (or up) aims from this frame's eye.
    if (movie.view_point) cam.view_point = evaluate(*movie.view_point, frame, n, cam.view_point);
    if (movie.look_at) cam.look_at = evaluate(*movie.look_at, frame, n, cam.view_point);
    if (movie.up) cam.up = evaluate(*movie.up, frame, n, cam.view_point);
    return cam;
}

std::vector<int> check_camera_path(const Movie& movie) {
    std::vector<int> parallel;
    const int n = movie.frame_count();
    for (int i = 0; i < n; ++i) {
        const Camera cam = camera_at(movie, i);
        // Checked before camera_basis, which would turn these into NaN.
        if (!is_finite(cam.look_at))
            throw std::invalid_argument("view direction is not finite at frame " + std::to_string(i));
        if (max_abs_component(cam.look_at) == 0)
            throw std::invalid_argument("view direction is zero-length at frame " + std::to_string(i));
        if (camera_basis(cam.look_at, cam.up).up_was_parallel) parallel.push_back(i);
    }
    return parallel;
}

}  // namespace fh
