// The frame the output benchmarks encode: Movie 1, frame 100 (800x800), one
// of the report's, rendered once per process.
#pragma once

#include "anim/movie.h"
#include "yaml/movie_loader.h"
#include "render/render.h"

namespace fh {

inline const Image& report_frame() {
    static const Image image = [] {
        const Movie movie = load_movie(FIRSTHIT_SOURCE_DIR "/animations/movie1.yaml");
        return render_frame(movie.scene, camera_at(movie, 100), movie.settings, nullptr)
            .image;
    }();
    return image;
}

}  // namespace fh
