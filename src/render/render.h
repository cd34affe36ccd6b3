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
// One frame in settings.precision's scalar type: the scene prepared for it
// (render/prepared_scene.h) and rendered. Movies prepare once instead.
FrameResult render_frame(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         ThreadPool* pool);

template <typename T>
struct FlatScene;
// A frame of a scene already flattened into T (float or double).
template <typename T>
FrameResult render_frame_as(const FlatScene<T>& scene, const Camera& camera, const RenderSettings& settings,
                            ThreadPool* pool);
extern template FrameResult render_frame_as<float>(const FlatScene<float>&, const Camera&, const RenderSettings&,
                                                   ThreadPool*);
extern template FrameResult render_frame_as<double>(const FlatScene<double>&, const Camera&,
                                                    const RenderSettings&, ThreadPool*);

inline constexpr int kTileSize = 16;

}  // namespace fh
