// Sphere (report 4.2): analytic ray/sphere intersection, normal = normalize(p - c).
//
// The textbook b^2 - 4ac loses every significant digit when the sphere is small
// against its distance (both terms ~ distance^2). We compute the discriminant
// from the ray's closest approach instead, r^2 - |f - (f.d)d|^2, whose terms
// are ~ r^2, and take the smaller-magnitude root as c/q so it does not cancel
// (Ray Tracing Gems, ch. 7). Requires a unit direction.
#pragma once

#include <algorithm>
#include <cmath>

#include "core/hit.h"
#include "core/ray.h"

namespace fh {

template <typename T>
struct Sphere {
    Vec3<T> center;
    T radius;
    int material;

    // Nearest t in (t_min, t_max), or infinity. Branch-free, so a loop of it
    // over a batch of rays vectorises (render/batch_intersect.h).
    FH_HOT_INLINE T intersect(const Ray<T>& ray, T t_min, T t_max) const {
        const Vec3<T> f = ray.origin - center;
        const T b = -glm::dot(f, ray.direction);  // t of the closest approach
        const Vec3<T> closest = f + b * ray.direction;
        const T r2 = radius * radius;
        const T disc = r2 - glm::dot(closest, closest);
        const T c = glm::dot(f, f) - r2;
        // q is the root of larger magnitude; the other is c / q (t0 t1 = c).
        // q == 0 only for a ray starting at a tangent point: c / q is then
        // NaN, every comparison below fails, and the ray misses.
        const T q = b + std::copysign(std::sqrt(std::max(disc, T(0))), b);
        const T t0 = c / q;
        const T near = std::min(t0, q);
        const T far = std::max(t0, q);
        const T t = near > t_min ? near : far;
        // & rather than &&: no branches, so loops over it vectorise.
        return ((disc >= T(0)) & (t > t_min) & (t < t_max)) ? t : kInfinity<T>;
    }

    Vec3<T> normal_at(const Vec3<T>& p) const { return glm::normalize(p - center); }

    // The hit point projected back onto the sphere, so its error is a few ulps
    // of its own coordinates rather than of the ray's travel.
    Vec3<T> point_at(const Ray<T>& ray, T t) const {
        return center + radius * normal_at(ray.at(t));
    }
};

}  // namespace fh
