// The sky a ray sees when it hits nothing (report 8.1): a sunset from red at
// the bottom to yellow at the top, with the ray's z.
//     s = clamp((dir.z + 1) / 2, 0, 1),  colour = (255, 255 s, 0)
#pragma once

#include <algorithm>

#include "core/vec.h"

namespace fh {

template <typename T>
inline Color<T> background(const Vec3<T>& direction) {
    const T s = std::clamp((direction.z + T(1)) / T(2), T(0), T(1));
    return {T(255), T(255) * s, T(0)};
}

}  // namespace fh
