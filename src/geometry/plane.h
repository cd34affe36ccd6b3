// Plane (report 4.3): n.x = d, d the distance along the normal from the origin.
// t = (d - n.o) / (n.dir); a ray (nearly) parallel to the plane never hits it.
#pragma once

#include "core/hit.h"
#include "core/ray.h"

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

    // Branch-free: with a (nearly) parallel ray the division may give inf or
    // NaN, which the mask discards.
    FH_HOT_INLINE T intersect(const Ray<T>& ray, T t_min, T t_max) const {
        const T denom = glm::dot(normal, ray.direction);
        const T t = (distance - glm::dot(normal, ray.origin)) / denom;
        const bool crosses = std::abs(denom) >= ParallelLimit<T>::value;
        return (crosses & (t > t_min) & (t < t_max)) ? t : kInfinity<T>;
    }

    Vec3<T> normal_at(const Vec3<T>&) const { return normal; }

    Vec3<T> point_at(const Ray<T>& ray, T t) const {
        const Vec3<T> p = ray.at(t);
        return p - (glm::dot(normal, p) - distance) * normal;
    }
};

}  // namespace fh
