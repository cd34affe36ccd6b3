// render_frame_in<float>, in a file of its own: render/render_frame_in.h.
#include "render/render_frame_in.h"

namespace fh {

template FrameResult render_frame_in<float>(const Scene&, const Camera&, const RenderSettings&, const Effects&,
                                            ThreadPool*);

}  // namespace fh
