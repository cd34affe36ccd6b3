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

namespace fh {

const char* const kViewHelp =
    R"(usage: firsthit view FILE [options]

Opens a window showing a frame of a scene or movie file, rendered at a quarter
of the resolution at once, then at full resolution.

  FILE               a scene file, or a movie file (which names its scene)
  --camera NAME      scene files: the camera shown first (default: the first listed)
  --frame N          movie files: the frame shown first (default 0)
  --spp N, --depth N, --precision P, --adaptive, --aa-threshold X, --aa-samples N,
  --no-prune         as for 'firsthit render' (the full-resolution image is the
                     same as 'firsthit render' gives)
  --threads N        worker threads (default: one per core)

keys:
  P                  switch camera projection: a scene file shows its next
                     camera with the other projection (orthographic <->
                     perspective); a movie keeps its camera path and flips
                     the projection
  Left / Right       previous / next frame (movies)
  Home / End         first / last frame (movies)
  Space              play / pause at the movie's fps (looping); frames follow
                     the clock, the resolution drops while rendering cannot
                     keep up
  S                  save the shown frame at full resolution as
                     view_STEM[_frameNNNN]_CAMERA.png in the current folder
                     (pauses playback); prints the path on stdout
  Q, Esc             quit

The title shows the file, frame, camera, image size and ms per frame.
Needs a display (X11 or Wayland); without one, exits 1 with one line.
Needs firsthit built with GLFW and OpenGL (apt-get install libglfw3-dev libgl-dev).
)";

}  // namespace fh

#ifndef FIRSTHIT_HAVE_VIEW

namespace fh {

int run_view(const Words& words) {
    if (wants_help(words, kViewHelp)) return 0;
    std::cerr << "firsthit: error: view is not built in; to enable it: apt-get install "
                 "libglfw3-dev libgl-dev, then rebuild (cmake -S . -B build && cmake --build build)\n";
    return 1;
}

}  // namespace fh

#else  // FIRSTHIT_HAVE_VIEW

#include "cli/job.h"
#include "view/viewer.h"

namespace fh {

int run_view(const Words& words) {
    if (wants_help(words, kViewHelp)) return 0;
    auto spec = job_flags();
    spec.push_back({"--threads"});
    const Args args = Args::parse("view", words, spec);
    one_file(args);  // before --threads, as the other commands check it first
    const int threads = args.integer("--threads", 0, 0, 1024);
    // Bad input is found (status 2) before a window is asked for.
    const Job job = job_from_args(args, "its camera is set in the file; P flips its projection");
    std::optional<view::ViewState> state;
    if (job.is_movie_file) state.emplace(job.file, job.movie, job.frame);
    else state.emplace(job.file, job.scene(), job.camera_index);

    const view::Glfw glfw;
    view::Viewer viewer(*state, job.scene(), job.settings(), threads);
    return viewer.run();
}

}  // namespace fh

#endif  // FIRSTHIT_HAVE_VIEW
