// Sphere (report 4.2): analytic ray/sphere intersection, normal = normalize(p - c).
//
// The textbook b^2 - 4ac loses every significant digit when the sphere is small
// against its distance (both terms ~ distance^2). We compute the discriminant
// from the ray's closest approach instead, r^2 - |f - (f.d)d|^2, whose terms
// are ~ r^2, and take the smaller-magnitude root as c/q so it does not cancel
// (Ray Tracing Gems, ch. 7). Two refinements keep the silhouette exact to a
// few ulps of r at any distance:
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
//
// The formula runs on a packet of rays (core/packet.h); one ray is a packet
// with that ray in every lane, so tests of one ray test the tracer's code.
#pragma once

#include <limits>

#include "core/exact.h"
#include "core/packet.h"
#include "geometry/aabb.h"
#include "geometry/surface.h"

namespace fh {

template <typename T>
struct Sphere {
    Vec3<T> center;
    T radius;
    int material;

    // Nearest t in (t_min, t_max) for each ray of a packet, or infinity.
    FH_HOT_INLINE Lanes<T> intersect(const RayPacket<T>& ray, T t_min, Lanes<T> t_max) const {
        const Vec3Lanes<T> f = ray.origin - center;
        const Lanes<T> b = -dot(f, ray.direction);  // t of the closest approach
        const Lanes<T> disc = discriminant(ray, f, b);
        // No ray of the packet meets the sphere: skip the square root and the
        // division. (Most packets, for most spheres.)
        const LaneInts<T> meets = (disc >= T(0)) & (t_max > t_min);
        if (none(meets)) return splat(kInfinity<T>);
        const T r2 = radius * radius;
        // c = |f|^2 - r^2 is zero, as far as the arithmetic and the origin's own
        // coordinates can tell, for an origin on the sphere: then exactly 0.
        const Lanes<T> f2 = dot(f, f);
        const Lanes<T> c_raw = f2 - r2;
        const T eps = std::numeric_limits<T>::epsilon();
        const Lanes<T> c_error = T(4) * eps * (f2 + r2 + radius * max_abs_component(ray.origin));
        const Lanes<T> c = select(abs(c_raw) <= c_error, splat(T(0)), c_raw);
        // Both roots at or behind the origin (their sum 2b < 0, their product
        // c >= 0): nothing ahead, as the formula below would find too. Every
        // shadow and reflection ray leaving a sphere's surface is such a ray
        // for that sphere: a packet of them skips the square root and division.
        if (none(meets & ((b >= T(0)) | (c < T(0))))) return splat(kInfinity<T>);
        // q is the root of larger magnitude; the other is c / q (t0 t1 = c).
        // q == 0 only for a ray starting at a tangent point: c / q is then
        // NaN, every comparison below fails, and the ray misses.
        const Lanes<T> q = b + copysign(sqrt(max(disc, splat(T(0)))), b);
        const Lanes<T> t0 = c / q;
        const Lanes<T> near = min(t0, q);
        const Lanes<T> far = max(t0, q);
        const Lanes<T> t = select(near > t_min, near, far);
        return select((disc >= T(0)) & (t > t_min) & (t < t_max), t, splat(kInfinity<T>));
    }

    // One ray: the packet formula with that ray in every lane.
    T intersect(const Ray<T>& ray, T t_min, T t_max) const {
        return intersect(RayPacket<T>::splat(ray), t_min, splat(t_max))[0];
    }

    Aabb bounds() const { return {dvec3(center) - double(radius), dvec3(center) + double(radius)}; }
    PrimitiveSurface<T> surface() const { return PrimitiveSurface<T>::round_about(center, radius, material); }
    template <typename U>
    Sphere<U> in() const {
        return {Vec3<U>(center), U(radius), material};
    }

private:
    // r^2 - |closest approach|^2, f = origin - center, b = -f.d.
    FH_HOT_INLINE Lanes<T> discriminant(const RayPacket<T>& ray, const Vec3Lanes<T>& f,
                                        const Lanes<T>& b) const {
        const Vec3Lanes<T>& d = ray.direction;
        const Vec3Lanes<T> closest{mul_add(b, d.x, f.x), mul_add(b, d.y, f.y), mul_add(b, d.z, f.z)};
        // closest.d ~ the rounding of b: its square is what that adds to |closest|^2.
        const Lanes<T> along = dot(closest, d);
        return mul_add(along, along, radius * radius - dot(closest, closest));
    }
};

}  // namespace fh
