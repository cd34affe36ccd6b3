#include "support/png_read.h"

#include <cstdlib>
#include <cstring>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb_image.h>
#pragma GCC diagnostic pop

namespace fh::test {

Image read_png(const std::string& path) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load(path.c_str(), &w, &h, &n, 3);
    if (!data) return {};
    Image img(w, h);
    std::memcpy(img.rgb.data(), data, img.rgb.size());
    stbi_image_free(data);
    return img;
}

ImageDiff compare(const Image& a, const Image& b) {
    ImageDiff d;
    if (a.width != b.width || a.height != b.height) {
        d.max_abs = 256;
        return d;
    }
    for (size_t i = 0; i < a.rgb.size(); ++i) {
        const int diff = std::abs(int(a.rgb[i]) - int(b.rgb[i]));
        d.max_abs = std::max(d.max_abs, diff);
        d.differing += diff > 0;
    }
    return d;
}

}  // namespace fh::test
