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

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>

#include "anim/movie.h"
#include "cli/job.h"
#include "io/png_writer.h"
#include "render/render.h"
#include "view/background_renderer.h"
#include "view/view_state.h"

namespace fh {

namespace {

using Clock = std::chrono::steady_clock;
using view::Renderer;
using view::Request;
using view::Result;

constexpr int kCoarseDivisor = 4;

struct Glfw {
    Glfw() {
        if (!glfwInit()) {
            const char* desc = nullptr;
            glfwGetError(&desc);
            std::string why = desc ? desc : "glfwInit failed";
            while (!why.empty() && (why.back() == ' ' || why.back() == '.')) why.pop_back();
            const char* d = std::getenv("DISPLAY");
            const char* wl = std::getenv("WAYLAND_DISPLAY");
            if ((!d || !*d) && (!wl || !*wl)) why = "DISPLAY is not set; " + why;
            throw std::runtime_error("view needs a display (" + why +
                                     "); set DISPLAY, or run under Xvfb: xvfb-run firsthit view FILE");
        }
    }
    ~Glfw() { glfwTerminate(); }
};

class Viewer {
public:
    Viewer(view::ViewState state, const Scene& scene, const RenderSettings& settings, int threads)
        : state_(std::move(state)), renderer_(scene, settings, threads) {}

    int run() {
        const Camera cam = state_.camera();
        int w = cam.width, h = cam.height;
        if (const GLFWvidmode* mode = glfwGetVideoMode(glfwGetPrimaryMonitor())) {
            // Fit on the screen, keeping the aspect ratio.
            const double k = std::min({1.0, 0.9 * mode->width / w, 0.9 * mode->height / h});
            w = std::max(1, int(w * k));
            h = std::max(1, int(h * k));
        }
        if (const int side = std::max(w, h); side < 256) {  // tiny images: whole-pixel zoom
            const int zoom = (256 + side - 1) / side;
            w *= zoom;
            h *= zoom;
        }
        glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
        window_ = glfwCreateWindow(w, h, "firsthit view", nullptr, nullptr);
        if (!window_) {
            const char* desc = nullptr;
            glfwGetError(&desc);
            throw std::runtime_error(std::string("view could not open an OpenGL window (") +
                                     (desc ? desc : "unknown reason") + ")");
        }
        glfwSetWindowUserPointer(window_, this);
        glfwSetKeyCallback(window_, [](GLFWwindow* win, int key, int, int action, int) {
            static_cast<Viewer*>(glfwGetWindowUserPointer(win))->on_key(key, action);
        });
        glfwSetWindowRefreshCallback(window_, [](GLFWwindow* win) {
            static_cast<Viewer*>(glfwGetWindowUserPointer(win))->redraw_ = true;
        });
        glfwSetFramebufferSizeCallback(window_, [](GLFWwindow* win, int, int) {
            static_cast<Viewer*>(glfwGetWindowUserPointer(win))->redraw_ = true;
        });
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(0);
        glGenTextures(1, &texture_);

        request_refined();
        while (!glfwWindowShouldClose(window_)) {
            glfwWaitEventsTimeout(playing_ ? 0.002 : 0.1);
            if (playing_) advance_playback();
            if (auto r = renderer_.take()) show(std::move(*r));
            if (redraw_) draw();
            maybe_save();
        }
        glDeleteTextures(1, &texture_);
        glfwDestroyWindow(window_);
        window_ = nullptr;
        return 0;
    }

private:
    void on_key(int key, int action) {
        if (action == GLFW_RELEASE) return;
        const bool repeat = action == GLFW_REPEAT;
        bool changed = false;
        switch (key) {
        case GLFW_KEY_Q:
        case GLFW_KEY_ESCAPE:
            glfwSetWindowShouldClose(window_, GLFW_TRUE);
            return;
        case GLFW_KEY_P:
            if (!repeat) changed = state_.switch_camera();
            break;
        case GLFW_KEY_LEFT: changed = state_.step(-1); break;
        case GLFW_KEY_RIGHT: changed = state_.step(+1); break;
        case GLFW_KEY_HOME: changed = state_.home(); break;
        case GLFW_KEY_END: changed = state_.end(); break;
        case GLFW_KEY_SPACE:
            if (!repeat) toggle_play();
            return;
        case GLFW_KEY_S:
            if (repeat) return;
            save_requested_ = true;
            if (playing_) stop_playing();  // save the frame shown now, refined
            return;
        default: return;
        }
        if (!changed) return;
        if (playing_) {  // a step while playing restarts the clock from there
            play_start_ = Clock::now();
            play_start_frame_ = state_.frame();
            play_requested_frame_ = -1;
        } else {
            request_refined();
        }
    }

    void toggle_play() {
        if (!state_.is_movie() || state_.frame_count() < 2) return;
        if (playing_) {
            stop_playing();
            return;
        }
        playing_ = true;
        play_start_ = Clock::now();
        play_start_frame_ = state_.frame();
        play_requested_frame_ = -1;
        update_title();
    }

    void stop_playing() {
        playing_ = false;
        // Stay on the frame last shown, then refine it.
        if (shown_) state_.set_frame(shown_->state.frame());
        request_refined();
    }

    // Pick the frame from the clock; render it when the renderer is free.
    void advance_playback() {
        const double elapsed = std::chrono::duration<double>(Clock::now() - play_start_).count();
        state_.set_frame(view::frame_at(play_start_frame_, elapsed, state_.fps(), state_.frame_count()));
        if (renderer_.busy() || (state_.frame() == play_requested_frame_ &&
                                 play_requested_camera_ == state_.camera().name))
            return;
        play_requested_frame_ = state_.frame();
        play_requested_camera_ = state_.camera().name;
        renderer_.submit(Request{++generation_, state_, play_divisor_, false});
    }

    void request_refined() {
        const Camera c = state_.camera();
        const int d = std::min(c.width, c.height) >= 4 * kCoarseDivisor ? kCoarseDivisor : 1;
        renderer_.submit(Request{++generation_, state_, d, true});
    }

    void show(Result r) {
        if (!playing_ && r.generation != generation_) return;  // superseded
        if (playing_ && r.divisor == play_divisor_)
            play_divisor_ = view::adapt_divisor(play_divisor_, r.ms, state_.fps());
        glBindTexture(GL_TEXTURE_2D, texture_);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, r.image.width, r.image.height, 0, GL_RGB,
                     GL_UNSIGNED_BYTE, r.image.rgb.data());
        shown_ = std::move(r);
        update_title();
        redraw_ = true;
    }

    void update_title() {
        if (!shown_) return;
        const std::string t = shown_->state.title(shown_->image.width, shown_->image.height,
                                                  shown_->ms, playing_);
        glfwSetWindowTitle(window_, t.c_str());
    }

    // The image fills the window, keeping its aspect ratio (bars around it).
    void draw() {
        redraw_ = false;
        int fw = 0, fh = 0;
        glfwGetFramebufferSize(window_, &fw, &fh);
        glViewport(0, 0, fw, fh);
        glClearColor(0.15f, 0.15f, 0.15f, 1);
        glClear(GL_COLOR_BUFFER_BIT);
        if (shown_ && fw > 0 && fh > 0) {
            const Camera c = shown_->state.camera();
            const double k = std::min(double(fw) / c.width, double(fh) / c.height);
            const int vw = std::max(1, int(std::lround(c.width * k)));
            const int vh = std::max(1, int(std::lround(c.height * k)));
            glViewport((fw - vw) / 2, (fh - vh) / 2, vw, vh);
            glMatrixMode(GL_PROJECTION);
            glLoadIdentity();
            glOrtho(0, 1, 1, 0, -1, 1);  // y down: row 0 of the image at the top
            glMatrixMode(GL_MODELVIEW);
            glLoadIdentity();
            glEnable(GL_TEXTURE_2D);
            glBindTexture(GL_TEXTURE_2D, texture_);
            glColor3f(1, 1, 1);
            glBegin(GL_QUADS);
            glTexCoord2f(0, 0); glVertex2f(0, 0);
            glTexCoord2f(1, 0); glVertex2f(1, 0);
            glTexCoord2f(1, 1); glVertex2f(1, 1);
            glTexCoord2f(0, 1); glVertex2f(0, 1);
            glEnd();
            glDisable(GL_TEXTURE_2D);
        }
        glfwSwapBuffers(window_);
    }

    // S: once the full-resolution image of what is shown is on screen.
    void maybe_save() {
        if (!save_requested_ || playing_ || !shown_ || shown_->divisor != 1 ||
            shown_->generation != generation_ || redraw_)
            return;
        save_requested_ = false;
        const std::string path = shown_->state.save_name();
        write_png(path, shown_->image);
        std::cout << path << std::endl;
    }

    view::ViewState state_;
    Renderer renderer_;
    GLFWwindow* window_ = nullptr;
    GLuint texture_ = 0;
    std::optional<Result> shown_;
    unsigned generation_ = 0;
    bool redraw_ = true;
    bool save_requested_ = false;
    bool playing_ = false;
    Clock::time_point play_start_;
    int play_start_frame_ = 0;
    int play_requested_frame_ = -1;
    std::string play_requested_camera_;
    int play_divisor_ = 1;
};

}  // namespace

int run_view(const Words& words) {
    if (wants_help(words, kViewHelp)) return 0;
    auto spec = job_flags();
    spec.push_back({"--threads"});
    const Args args = Args::parse("view", words, spec);
    const int threads = args.integer("--threads", 0, 0, 1024);
    // Bad input is found (status 2) before a window is asked for.
    const Job job = load_job_from(args);
    std::optional<view::ViewState> state;
    if (job.is_movie_file) state.emplace(job.file, job.movie, job.frame);
    else state.emplace(job.file, job.scene(), job.camera_index);

    const Glfw glfw;
    Viewer viewer(*state, job.scene(), job.settings(), threads);
    return viewer.run();
}

}  // namespace fh

#endif  // FIRSTHIT_HAVE_VIEW
