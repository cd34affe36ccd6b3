// Where a secondary ray (shadow or reflection) starts. Starting exactly on the
// surface lets rounding put the origin just behind it, so the ray hits its own
// surface ("acne"). Every shape projects its hit point back onto itself, which
// leaves an error of a few ulps of the point's own coordinates; we push the
// origin along the normal, to the side the new ray leaves from, by a margin
// well above that error. The margin is relative to the point's magnitude, so it
// holds for a scene scaled by 1e-3 as for one moved 1e6 away from the origin.
#pragma once

#include "core/packet.h"

namespace fh {

template <typename T>
struct OffsetScale;
template <>
struct OffsetScale<float> {
    static constexpr float relative = 1e-5f;  // ~80 ulps
    static constexpr float absolute = 1e-7f;
};
template <>
struct OffsetScale<double> {
    static constexpr double relative = 1e-9;  // ~4.5e6 ulps; far below any feature size
    static constexpr double absolute = 1e-15;
};

// For each lane; normal: unit, pointing to the side the new ray travels into.
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> offset_origin(const Vec3Lanes<T>& point, const Vec3Lanes<T>& normal) {
    const Lanes<T> eps = OffsetScale<T>::absolute + OffsetScale<T>::relative * max_abs_component(point);
    return point + eps * normal;
}

// One point: the packet formula with that point in every lane.
template <typename T>
Vec3<T> offset_origin(const Vec3<T>& point, const Vec3<T>& normal) {
    return offset_origin(Vec3Lanes<T>::splat(point), Vec3Lanes<T>::splat(normal)).lane(0);
}

}  // namespace fh
