// Plane (report 4.3): n.x = d, d the distance along the normal from the origin.
// t = (d - n.o) / (n.dir); a ray (nearly) parallel to the plane never hits it.
#pragma once

#include "core/packet.h"
#include "geometry/surface.h"

namespace fh {

template <typename T>
struct ParallelLimit;
// |n.dir| below this counts as parallel: past it t would exceed ~1e6 (float)
// or ~1e7 (double) plane-distances, far beyond anything a pixel can resolve.
template <>
struct ParallelLimit<float> {
    static constexpr float value = 1e-6f;
};
template <>
struct ParallelLimit<double> {
    static constexpr double value = 1e-7;
};

template <typename T>
struct Plane {
    Vec3<T> normal;  // unit
    T distance;
    int material;

    // Nearest t in (t_min, t_max) for each ray of a packet, or infinity. With
    // a (nearly) parallel ray the division may give inf or NaN, which the
    // mask discards.
    FH_HOT_INLINE Lanes<T> intersect(const RayPacket<T>& ray, T t_min, Lanes<T> t_max) const {
        const Lanes<T> denom = dot(normal, ray.direction);
        const Lanes<T> height = distance - dot(normal, ray.origin);  // t = height / denom
        // No ray of the packet heads toward the plane (t <= 0: most shadow
        // and reflection rays leave it): skip the division.
        if (none((height * denom > T(0)) & (t_max > t_min))) return splat(kInfinity<T>);
        const Lanes<T> t = height / denom;
        const LaneInts<T> crosses = abs(denom) >= ParallelLimit<T>::value;
        return select(crosses & (t > t_min) & (t < t_max), t, splat(kInfinity<T>));
    }

    // One ray: the packet formula with that ray in every lane.
    T intersect(const Ray<T>& ray, T t_min, T t_max) const {
        return intersect(RayPacket<T>::splat(ray), t_min, splat(t_max))[0];
    }

    PrimitiveSurface<T> surface() const {
        return PrimitiveSurface<T>::flat_through(distance * normal, normal, material);
    }
    template <typename U>
    Plane<U> in() const {
        return {Vec3<U>(normal), U(distance), material};
    }
};

}  // namespace fh
