// The window of `firsthit view` (GLFW + OpenGL): shows the latest image of
// the background renderer, turns keys into ViewState changes, plays a movie
// on the clock and saves the shown frame. Included by view_command.cpp only,
// and only when CMake found GLFW and OpenGL.
#pragma once

#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

#include "anim/movie.h"
#include "images/png_writer.h"
#include "render/render.h"
#include "view/background_renderer.h"
#include "view/view_state.h"

namespace fh::view {

using Clock = std::chrono::steady_clock;

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
    // movie: the movie shown (its scene may move), or nullptr for a scene.
    Viewer(ViewState state, const Scene& scene, const RenderSettings& settings, int threads,
           const Movie* movie = nullptr)
        : state_(std::move(state)), renderer_(scene, settings, threads, movie) {}

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
        state_.set_frame(frame_at(play_start_frame_, elapsed, state_.fps(), state_.frame_count()));
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
            play_divisor_ = adapt_divisor(play_divisor_, r.ms, state_.fps());
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

    ViewState state_;
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

}  // namespace fh::view
