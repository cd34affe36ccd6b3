// Sphere (report 4.2): analytic ray/sphere intersection, normal = normalize(p - c).
//
// The textbook b^2 - 4ac loses every significant digit when the sphere is small
// against its distance (both terms ~ distance^2). We compute the discriminant
// from the ray's closest approach instead, r^2 - |f - (f.d)d|^2, whose terms
// are ~ r^2, and take the smaller-magnitude root as c/q so it does not cancel
// (Ray Tracing Gems, ch. 7). Two refinements keep the silhouette exact to a
// few ulps of r at any distance (issue 4, test_sphere_robust.cpp):
//  - the closest approach f + b d is formed with fused multiply-adds, so the
//    products b d, as large as the distance, are not rounded before they
//    cancel against f;
//  - b itself carries the rounding of f.d, which moves that point along d (as
//    does a direction that is unit only to rounding); the square of that
//    component, (closest.d)^2, is taken back out of |closest|^2.
// And a ray that starts on the sphere, to the rounding of its coordinates,
// has c = |f|^2 - r^2 = 0 exactly: its root at the origin (t = 0) never
// counts as a hit ahead of it, so it finds the far side going in and nothing
// going out. Requires a unit direction (to rounding).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/exact.h"
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
        const T disc = discriminant(ray, f, b);
        const T r2 = radius * radius;
        // c = |f|^2 - r^2 is zero, as far as the arithmetic and the origin's own
        // coordinates can tell, for an origin on the sphere: then exactly 0.
        const T f2 = glm::dot(f, f);
        const T c_raw = f2 - r2;
        const T eps = std::numeric_limits<T>::epsilon();
        const T c_error = T(4) * eps * (f2 + r2 + radius * max_abs_component(ray.origin));
        const T c = std::abs(c_raw) <= c_error ? T(0) : c_raw;
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

    // The ray's line meets the sphere iff this is >= 0: the first step of
    // intersect() on its own, so a batch none of whose rays can hit skips
    // the rest (render/batch_intersect.h).
    FH_HOT_INLINE T discriminant(const Ray<T>& ray) const {
        const Vec3<T> f = ray.origin - center;
        return discriminant(ray, f, -glm::dot(f, ray.direction));
    }

    Vec3<T> normal_at(const Vec3<T>& p) const { return glm::normalize(p - center); }

    // The hit point projected back onto the sphere, so its error is a few ulps
    // of its own coordinates rather than of the ray's travel.
    Vec3<T> point_at(const Ray<T>& ray, T t) const {
        return center + radius * normal_at(ray.at(t));
    }

private:
    // r^2 - |closest approach|^2, f = origin - center, b = -f.d.
    FH_HOT_INLINE T discriminant(const Ray<T>& ray, const Vec3<T>& f, T b) const {
        const Vec3<T>& d = ray.direction;
        const Vec3<T> closest(mul_add(b, d.x, f.x), mul_add(b, d.y, f.y), mul_add(b, d.z, f.z));
        // closest.d ~ the rounding of b: its square is what that adds to |closest|^2.
        const T along = glm::dot(closest, d);
        return mul_add(along, along, radius * radius - glm::dot(closest, closest));
    }
};

}  // namespace fh
