// render_frame<float>, in a file of its own: render/tile_renderer.h.
#include "render/tile_renderer.h"

namespace fh {

template FrameResult render_frame<float>(const Scene&, const Camera&, const RenderSettings&, ThreadPool*);

}  // namespace fh
