// Disk: the points of a plane within `radius` of `center`. A ray meets its
// plane as it meets a Plane (geometry/plane.h), at t = n.(c - o) / n.d, and
// hits where that point lies within the radius.
#pragma once

#include <cmath>

#include "core/packet.h"
#include "geometry/aabb.h"
#include "geometry/plane.h"
#include "geometry/surface.h"

namespace fh {

template <typename T>
struct Disk {
    Vec3<T> center;
    Vec3<T> normal;  // unit
    T radius;
    int material;

    // Nearest t in (t_min, t_max) for each ray of a packet, or infinity.
    FH_HOT_INLINE Lanes<T> intersect(const RayPacket<T>& ray, T t_min, Lanes<T> t_max) const {
        const Lanes<T> denom = dot(normal, ray.direction);
        const Lanes<T> height = dot(normal, center - ray.origin);  // t = height / denom
        // No ray of the packet heads toward the disk's plane: skip the division.
        if (none((height * denom > T(0)) & (t_max > t_min))) return splat(kInfinity<T>);
        const Lanes<T> t = height / denom;
        const Vec3Lanes<T> from_center = ray.at(t) - center;
        const LaneInts<T> inside = dot(from_center, from_center) <= radius * radius;
        const LaneInts<T> crosses = abs(denom) >= ParallelLimit<T>::value;
        return select(inside & crosses & (t > t_min) & (t < t_max), t, splat(kInfinity<T>));
    }

    // One ray: the packet formula with that ray in every lane.
    T intersect(const Ray<T>& ray, T t_min, T t_max) const {
        return intersect(RayPacket<T>::splat(ray), t_min, splat(t_max))[0];
    }

    // Along each axis the disk reaches radius * sqrt(1 - n_axis^2) from its centre.
    Aabb bounds() const {
        const dvec3 n(normal), c(center);
        const dvec3 reach = double(radius) * glm::sqrt(glm::max(dvec3(0), dvec3(1) - n * n));
        return {c - reach, c + reach};
    }
    PrimitiveSurface<T> surface() const { return PrimitiveSurface<T>::flat_through(center, normal, material); }
    template <typename U>
    Disk<U> in() const {
        return {Vec3<U>(center), Vec3<U>(normal), U(radius), material};
    }
};

}  // namespace fh
