// How far an image is from a reference: what the accuracy sweep reports.
#pragma once

#include "render/image.h"

namespace fh {

struct ImageError {
    double rmse = 0;       // over all channels, in 0..255 units
    double psnr = 0;       // 20 log10(255 / rmse) dB; infinite for identical images
    int max_error = 0;     // the worst channel difference
    double differing = 0;  // fraction of pixels with any channel off
};

// Images must have the same size.
ImageError compare_images(const Image& image, const Image& reference);

}  // namespace fh
