// The movie pipeline: the selected frames of a movie rendered on a thread
// pool, written to FOLDER/frame_NNNN.png whole or not at all, optionally
// streamed in order as raw video for an encoder, resumable, and stopped
// cleanly by SIGINT/SIGTERM. Frames are spread over the pool one per worker:
// each worker renders its frame alone and encodes its PNG, so encoding runs
// beside rendering instead of stalling it. A frame's bytes depend only on
// its index, never on the selection, the order or the thread count.
#pragma once

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "anim/movie.h"
#include "pipeline/frame_files.h"
#include "pipeline/job.h"
#include "video/raw_video_writer.h"
#include "render/render.h"

namespace fh {

struct FramesRequest {
    std::vector<int> frames;  // which frames, increasing (anim/frame_selection.h)
    FrameFiles files;         // where they go (pipeline/frame_files.h)
    std::string movie_file;   // the movie's file, for the frames' movie file
    std::string render;       // what else decides the pixels, for it too (FramesOrigin::render)
    bool resume = false;      // skip the frames whose file is already complete
    bool clean = false;       // remove frames of another movie or size under the same names
    // Also every frame in order to this file ("-": standard output); needs
    // the whole selection rendered, so not with resume.
    std::optional<std::string> raw_video;
    RawPixelFormat raw_pixel_format = RawPixelFormat::rgb24;
    int threads = 0;  // 0: one per core
    // After SIGINT/SIGTERM, frames in flight may take this long to finish
    // before the run abandons them and the process exits.
    std::chrono::milliseconds interrupt_grace{500};
};

// What the pipeline tells its caller while it runs (a command's progress
// line). frame_done is called from worker threads, one at a time.
class FramesObserver {
public:
    virtual ~FramesObserver() = default;
    virtual void removed_temporaries(int /*count*/) {}
    virtual void removed_old_frames(int /*count*/) {}
    virtual void starting(int /*frames_to_render*/) {}
    virtual void frame_done(int /*frame*/) {}
    // A signal came and the frames in flight overran the grace period: the
    // process exits with 128 + signal right after this returns.
    virtual void abandoning(int /*done*/, int /*total*/) {}
};

struct FramesSummary {
    double prepare_ms = 0;  // flattening the scene and building its BVH, once
    int rendered = 0;
    int to_render = 0;  // the selection less the frames resume skipped
    double seconds = 0;
    RayCounts counts;
    size_t refined_pixels = 0;  // adaptive anti-aliasing's second pass, all frames
    int interrupt_signal = 0;  // the run stopped early on this signal (0: it did not)
};

// Prepares the folder (created if missing; stale temporaries of killed runs
// removed; frames of another movie or size refused, or removed with clean;
// the frames' movie file written: claim_frame_folder), then renders. Throws
// InputError for a bad folder, UsageError for another movie's frames or raw
// video with resume.
FramesSummary render_frames(const Movie& movie, const RenderSettings& settings, const FramesRequest& request,
                            FramesObserver& observer);

// The job's frame rendered on `threads` workers (0: one per core) and
// written to `path` in the format its extension names (images/image_writer.h;
// "-": PNG to standard output), whole or not at all. The place is checked before
// rendering (InputError). SIGINT/SIGTERM during the render ends the process
// at once with 128 + signal and nothing written; during the write, the
// write finishes first.
struct StillResult {
    FrameResult frame;
    int threads = 0;  // the workers it ran on
};
StillResult render_to_file(const Job& job, const std::string& path, int threads);

// The job's frame rendered `runs` times after a warm-up run (bench): each
// run's milliseconds, and the last run's result.
struct FrameTimings {
    double prepare_ms = 0;    // flattening the scene and building its BVH, once
    double bvh_build_ms = 0;  // of which the BVH
    int bvh_nodes = 0;
    size_t instances = 0;     // the second level's
    // A movie that animates its scene: what the pipeline does before each
    // frame -- the frame's values written (scene_at) and the prepared scene
    // updated (for_frame: moved shapes refitted, moved instances placed) --
    // median over the runs; -1 for a still.
    double frame_update_ms = -1;
    std::vector<double> ms;   // rendering only
    FrameResult last;
    int threads = 0;
};
FrameTimings time_frame(const Job& job, int runs, int threads);

}  // namespace fh
