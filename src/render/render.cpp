#include "render/render.h"

#include "render/tile_renderer.h"

namespace fh {

template FrameResult render_frame_as<double>(const Scene&, const Camera&, const RenderSettings&, ThreadPool*);

FrameResult render_frame(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         ThreadPool* pool) {
    if (settings.precision == Precision::float32) return render_frame_as<float>(scene, camera, settings, pool);
    return render_frame_as<double>(scene, camera, settings, pool);
}

}  // namespace fh
