#include "render/render.h"

#include "render/render_frame_in.h"

namespace fh {

template FrameResult render_frame_in<double>(const Scene&, const Camera&, const RenderSettings&, const Effects&,
                                             ThreadPool*);

FrameResult render_frame(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         const Effects& effects, ThreadPool* pool) {
    if (settings.precision == Precision::single)
        return render_frame_in<float>(scene, camera, settings, effects, pool);
    return render_frame_in<double>(scene, camera, settings, effects, pool);
}

}  // namespace fh
