#include "scene/texture.h"

namespace fh {

// Filled once before main: the table every texel read goes through.
const std::array<float, 256> kSrgbToLinear = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
        const double c = i / 255.0;
        t[size_t(i)] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
}();

}  // namespace fh
