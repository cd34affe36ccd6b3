// The sky a ray sees when it hits nothing (report 8.1): a sunset from red at
// the bottom to yellow at the top, with the ray's z.
//     s = clamp((dir.z + 1) / 2, 0, 1),  colour = (255, 255 s, 0)
#pragma once

#include "core/packet.h"

namespace fh {

// For each ray of a packet.
template <typename T>
FH_HOT_INLINE ColorLanes<T> background(const Vec3Lanes<T>& direction) {
    const Lanes<T> s = (direction.z + T(1)) / T(2);
    const Lanes<T> clamped = select(s < T(0), splat(T(0)), select(T(1) < s, splat(T(1)), s));
    return {splat(T(255)), T(255) * clamped, splat(T(0))};
}

// One ray: the packet formula with that direction in every lane.
template <typename T>
Color<T> background(const Vec3<T>& direction) {
    return background(Vec3Lanes<T>::splat(direction)).lane(0);
}

}  // namespace fh
