// Adaptive anti-aliasing, in the spirit of POV-Ray's +AM: after a first pass,
// the pixels that differ from a neighbour by more than a threshold (on any
// channel, 0..255) are rendered again with more samples; smooth regions keep
// their one sample. Which pixels are refined depends only on the first pass's
// bytes, so the image is the same for any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "render/image.h"

namespace fh {

struct PixelRef {
    std::uint16_t x, y;
};

// Pixels with a neighbour (8-neighbourhood) more than `threshold` away on
// some channel, in row order.
std::vector<PixelRef> pixels_to_refine(const Image& first_pass, double threshold);

}  // namespace fh
