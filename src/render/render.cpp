// render_frame_as<double>; render_frame_as<float> is in render_float.cpp,
// render_frame in prepared_scene.cpp.
#include "render/tile_renderer.h"

namespace fh {

template FrameResult render_frame_as<double>(const FlatScene<double>&, const Camera&, const RenderSettings&,
                                             ThreadPool*);

}  // namespace fh
