// The view's background render thread: renders the latest request (a view
// state, first coarse, then at full resolution) while the window keeps
// answering; a newer request replaces one not yet started and ends a
// refinement before its next pass. A movie whose scene moves -- its paths,
// its glTF files' animations, skins and morphs -- shows each frame's scene,
// updated from the one prepared once as `frames` does it.
#pragma once

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include "anim/movie.h"
#include "render/prepared_scene.h"
#include "view/view_state.h"

namespace fh::view {

// What the render thread is asked for: the state to show, rendered first at
// 1/divisor of the resolution and then, if refine, at full resolution.
struct Request {
    unsigned generation = 0;
    ViewState state;
    int divisor = 1;
    bool refine = false;
};

struct Result {
    unsigned generation = 0;
    ViewState state;  // what the image shows
    int divisor = 1;
    Image image;
    double ms = 0;
};

// One background thread rendering the latest request; a newer request
// replaces one not yet started and ends a refinement before its next pass.
class Renderer {
public:
    // movie: the movie shown, or nullptr for a scene file.
    Renderer(const Scene& scene, const RenderSettings& settings, int threads, const Movie* movie = nullptr)
        : settings_(settings), pool_(threads), prepared_(movie ? movie->scene : scene, settings, &pool_),
          movie_(movie && movie->scene_changes() ? movie : nullptr),
          moves_(movie ? movie->shape_changes() : ShapeChanges{}), thread_([this] { loop(); }) {}

    ~Renderer() {
        {
            const std::lock_guard lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }

    void submit(Request r) {
        {
            const std::lock_guard lock(mutex_);
            pending_ = std::move(r);
            busy_ = true;
        }
        wake_.notify_all();
    }

    // The newest finished image, if one arrived since the last call.
    std::optional<Result> take() {
        const std::lock_guard lock(mutex_);
        if (error_) std::rethrow_exception(error_);
        std::optional<Result> r = std::move(result_);
        result_.reset();
        return r;
    }

    bool busy() const {
        const std::lock_guard lock(mutex_);
        return busy_;
    }

private:
    void loop() {
        std::unique_lock lock(mutex_);
        for (;;) {
            wake_.wait(lock, [&] { return stopping_ || pending_.has_value(); });
            if (stopping_) return;
            Request req = std::move(*pending_);
            pending_.reset();
            lock.unlock();
            try {
                render_passes(req);
            } catch (...) {
                lock.lock();
                error_ = std::current_exception();
                busy_ = false;
                lock.unlock();
                glfwPostEmptyEvent();
                lock.lock();
                continue;
            }
            lock.lock();
            if (!pending_) busy_ = false;
        }
    }

    void render_passes(const Request& req) {
        const Camera full = req.state.camera();
        std::optional<PreparedScene> frame;  // a moving scene at the frame shown
        if (movie_ && req.state.is_movie()) {
            if (!frame_scene_) frame_scene_.emplace(movie_->scene);
            scene_at(*movie_, req.state.frame(), *frame_scene_);
            frame.emplace(prepared_.for_frame(*frame_scene_, moves_, &pool_));
        }
        const PreparedScene& prepared = frame ? *frame : prepared_;
        int divisor = req.divisor;
        for (;;) {
            RenderSettings s = settings_;
            if (divisor > 1) {  // a preview: one sample per pixel is enough
                s.samples_per_pixel = 1;
                s.adaptive = false;
            }
            FrameResult fr = prepared.render(view::reduced(full, divisor), &pool_, s);
            {
                const std::lock_guard lock(mutex_);
                result_ = Result{req.generation, req.state, divisor, std::move(fr.image), fr.render_ms};
            }
            glfwPostEmptyEvent();  // wake the window's event loop
            if (!req.refine || divisor == 1) return;
            {
                const std::lock_guard lock(mutex_);
                if (pending_ || stopping_) return;  // superseded
            }
            divisor = 1;
        }
    }

    RenderSettings settings_;
    ThreadPool pool_;
    const PreparedScene prepared_;  // the geometry and its BVH, once for every frame shown
    const Movie* movie_;            // a movie whose scene moves, or nullptr
    ShapeChanges moves_;
    std::optional<Scene> frame_scene_;  // the render thread's: set to each frame shown
    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Request> pending_;
    std::optional<Result> result_;
    std::exception_ptr error_;
    bool busy_ = false;
    bool stopping_ = false;
    std::thread thread_;  // last: started once everything above exists
};

}  // namespace fh::view
