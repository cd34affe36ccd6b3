// firsthit view FILE: the report's window. Shows a scene's or
// movie's frame, refined progressively (a quarter-resolution image at once,
// then full resolution); P switches between orthographic and perspective,
// Left/Right/Home/End move through a movie, Space plays it at its fps, S saves
// the shown frame, Q or Esc quits. Rendering runs on a background thread, so
// the window always answers.
//
// Built only when CMake finds GLFW and OpenGL (FIRSTHIT_HAVE_VIEW); otherwise
// `firsthit view` says how to enable it and exits 1.
#include <iostream>

#include "cli/commands.h"

#ifndef FIRSTHIT_HAVE_VIEW

namespace fh {

int run_view(const Args&) {
    std::cerr << "firsthit: error: view is not built in; to enable it: apt-get install "
                 "libglfw3-dev libgl-dev, then rebuild (cmake -S . -B build && cmake --build build)\n";
    return 1;
}

}  // namespace fh

#else  // FIRSTHIT_HAVE_VIEW

#include "cli/job.h"
#include "view/viewer.h"

namespace fh {

int run_view(const Args& args) {
    one_file(args);  // before --threads, as the other commands check it first
    const int threads = args.integer("--threads", 0, 0, 1024);
    // Bad input is found (status 2) before a window is asked for.
    const Job job = job_from_args(args, "its camera is set in the file; P flips its projection");
    std::optional<view::ViewState> state;
    if (job.is_movie_file) state.emplace(job.file, job.movie, job.frame);
    else state.emplace(job.file, job.scene(), job.camera_index);

    const view::Glfw glfw;
    view::Viewer viewer(*state, job.scene(), job.settings(), threads, job.is_movie_file ? &job.movie : nullptr);
    return viewer.run();
}

}  // namespace fh

#endif  // FIRSTHIT_HAVE_VIEW
