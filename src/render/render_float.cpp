// render_frame_as<float>, in a file of its own: render/tile_renderer.h.
#include "render/tile_renderer.h"

namespace fh {

template FrameResult render_frame_as<float>(const FlatScene<float>&, const Camera&, const RenderSettings&,
                                            ThreadPool*);

}  // namespace fh
