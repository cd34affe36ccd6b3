// Rendering one frame: the image is cut into tiles handed out to a thread
// pool; each pixel depends only on its own coordinates, so the bytes are the
// same for any number of threads.
#pragma once

#include "render/flat_scene.h"
#include "render/image.h"
#include "render/settings.h"
#include "render/stats.h"
#include "render/thread_pool.h"
#include "scene/scene.h"

namespace fh {

struct FrameResult {
    Image image;
    RayCounts counts;
    EffectPlan plan;
    size_t refined_pixels = 0;  // adaptive anti-aliasing's second pass
    double render_ms = 0;
};

// pool == nullptr renders on the calling thread only (the frame generator
// runs one frame per worker that way).
// In settings.precision's scalar type.
FrameResult render_frame(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         ThreadPool* pool);
// In T (float or double), whatever settings.precision says.
template <typename T>
FrameResult render_frame_as(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                            ThreadPool* pool);
extern template FrameResult render_frame_as<float>(const Scene&, const Camera&, const RenderSettings&, ThreadPool*);
extern template FrameResult render_frame_as<double>(const Scene&, const Camera&, const RenderSettings&, ThreadPool*);

inline constexpr int kTileSize = 16;

}  // namespace fh
