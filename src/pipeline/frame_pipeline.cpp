#include "pipeline/frame_pipeline.h"

#include <algorithm>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <mutex>
#include <shared_mutex>

#include "anim/frame_selection.h"
#include "files/atomic_file.h"
#include "text/input_error.h"
#include "images/image_writer.h"
#include "images/png_writer.h"
#include "pipeline/interrupt.h"
#include "render/prepared_scene.h"

namespace fh {

namespace {
using Clock = std::chrono::steady_clock;
// Frames the raw video may hold, finished early, waiting for their turn.
constexpr int kRawVideoWindow = 8;
}  // namespace

FramesSummary render_frames(const Movie& movie, const RenderSettings& settings, const FramesRequest& request,
                            FramesObserver& observer) {
    if (request.raw_video && request.resume)
        throw UsageError("raw video streams whole runs of frames: not with resume");
    const FrameFiles& files = request.files;
    const int n = movie.frame_count();
    if (request.clean && request.resume) throw UsageError("clean removes the frames resume would keep: not both");
    const FramesOrigin origin{std::filesystem::absolute(request.movie_file).lexically_normal().string(), n, movie.fps,
                              movie.camera.width, movie.camera.height, files.pattern(n), request.render};
    if (const int removed = claim_frame_folder(files, origin, request.clean)) observer.removed_old_frames(removed);
    if (const int removed = remove_stale_temporaries(files.folder.string())) observer.removed_temporaries(removed);

    std::vector<int> frames = request.frames;
    if (request.resume)
        std::erase_if(frames, [&](int i) { return is_complete_png(files.path(i, n).string()); });
    std::optional<RawVideoWriter> raw_video;
    if (request.raw_video) raw_video.emplace(*request.raw_video, kRawVideoWindow, request.raw_pixel_format);

    FramesSummary summary;
    summary.to_render = int(frames.size());
    observer.starting(summary.to_render);
    const auto start = Clock::now();
    // Frames are written under a shared lock; the interrupt watch takes it
    // alone before ending the process, so no file is half written then.
    std::shared_mutex write_mutex;
    std::atomic<bool> finished{false};
    std::atomic<int> done{0};
    const InterruptWatch watch(request.interrupt_grace, [&](int sig) {
        std::unique_lock lock(write_mutex);
        if (finished) return;  // the run ended meanwhile: it reports itself
        observer.abandoning(done, summary.to_render);
        std::_Exit(128 + sig);
    });
    ThreadPool pool(request.threads);
    // The geometry and its BVH, built once. A frame whose lights or
    // materials change re-flattens those only; one whose shapes move
    // refits a copy (PreparedScene::for_frame).
    const PreparedScene prepared(movie.scene, settings, &pool);
    summary.prepare_ms = prepared.build_ms();
    const bool scene_changes = movie.scene_changes();
    const ShapeChanges shapes_move = movie.shape_changes();
    // Each worker's own copy of the scene, set to its frame's values.
    std::vector<std::optional<Scene>> worker_scenes(size_t(pool.size()));
    std::mutex counts_mutex;
    pool.parallel_for(summary.to_render, [&](int task, int worker) {
        if (interrupted()) return;
        const int i = frames[size_t(task)];
        FrameResult r;
        try {
            if (scene_changes) {
                std::optional<Scene>& scene = worker_scenes[size_t(worker)];
                if (!scene) scene = movie.scene;
                scene_at(movie, i, *scene);
                r = prepared.for_frame(*scene, shapes_move).render(camera_at(movie, i), nullptr);
            } else {
                r = prepared.render(camera_at(movie, i), nullptr);
            }
            {
                std::shared_lock lock(write_mutex);
                write_png(files.path(i, n).string(), r.image);
            }
            if (raw_video) raw_video->put(task, std::move(r.image));
        } catch (const std::exception& e) {
            if (raw_video) raw_video->fail(e.what());  // frames after this one wait for it
            throw;
        }
        {
            std::lock_guard lock(counts_mutex);
            summary.counts += r.counts;
            summary.refined_pixels += r.refined_pixels;
            ++done;
            observer.frame_done(i);
        }
    });
    {
        std::unique_lock lock(write_mutex);
        finished = true;
    }
    summary.rendered = done;
    summary.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (interrupted()) summary.interrupt_signal = interrupt_signal();
    return summary;
}

StillResult render_to_file(const Job& job, const std::string& path, int threads) {
    image_format_of(path);  // before rendering: a bad name or place is bad input
    if (path != "-") check_output_file(path);
    std::mutex write_mutex;
    bool written = false;
    const InterruptWatch watch(std::chrono::milliseconds(0), [&](int sig) {
        write_mutex.lock();  // held until the process ends
        if (written) {       // too late to stop: the run ends normally
            write_mutex.unlock();
            return;
        }
        std::fputs("firsthit: interrupted; nothing written\n", stderr);
        std::_Exit(128 + sig);
    });
    ThreadPool pool(threads);
    StillResult r{PreparedScene(job.scene(), job.settings(), &pool).render(job.camera, &pool), pool.size()};
    const std::lock_guard lock(write_mutex);
    write_image(path, r.frame.image);
    written = true;
    return r;
}

namespace {

// The median of `runs` updates to the job's frame from the movie's first
// state, as render_frames makes them (one worker's scene, reused).
double time_frame_update(const Job& job, int runs, ThreadPool& pool) {
    const Movie& movie = job.movie;
    const PreparedScene prepared(movie.scene, movie.settings, &pool);
    const ShapeChanges changes = movie.shape_changes();
    Scene scene = movie.scene;
    std::vector<double> ms;
    for (int i = 0; i <= runs; ++i) {
        const auto start = std::chrono::steady_clock::now();
        scene_at(movie, job.frame, scene);
        const PreparedScene frame = prepared.for_frame(scene, changes);
        const double took = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (i > 0) ms.push_back(took);  // the first warms up
    }
    std::sort(ms.begin(), ms.end());
    return ms[ms.size() / 2];
}

}  // namespace

FrameTimings time_frame(const Job& job, int runs, int threads) {
    ThreadPool pool(threads);
    FrameTimings t;
    t.threads = pool.size();
    const PreparedScene prepared(job.scene(), job.settings(), &pool);
    t.prepare_ms = prepared.build_ms();
    t.bvh_build_ms = prepared.bvh_build_ms();
    t.bvh_nodes = prepared.bvh_nodes();
    t.instances = prepared.instances();
    t.last = prepared.render(job.camera, &pool);  // warm-up
    for (int i = 0; i < runs; ++i) {
        t.last = prepared.render(job.camera, &pool);
        t.ms.push_back(t.last.render_ms);
    }
    if (job.frame >= 0 && job.movie.scene_changes()) t.frame_update_ms = time_frame_update(job, runs, pool);
    return t;
}

}  // namespace fh
