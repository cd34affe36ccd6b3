#include "render/image_compare.h"

#include <cmath>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace fh {

ImageError compare_images(const Image& image, const Image& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("compare_images: the images differ in size");
    ImageError e;
    double sum_sq = 0;
    size_t differing = 0;
    for (size_t p = 0; p < image.rgb.size(); p += 3) {
        bool off = false;
        for (size_t c = 0; c < 3; ++c) {
            const int d = std::abs(int(image.rgb[p + c]) - int(reference.rgb[p + c]));
            sum_sq += double(d) * d;
            e.max_error = std::max(e.max_error, d);
            off |= d != 0;
        }
        differing += off;
    }
    const double n = double(image.rgb.size());
    e.rmse = n > 0 ? std::sqrt(sum_sq / n) : 0;
    e.psnr = e.rmse > 0 ? 20 * std::log10(255 / e.rmse) : std::numeric_limits<double>::infinity();
    e.differing = n > 0 ? double(differing) / (n / 3) : 0;
    return e;
}

}  // namespace fh
