// Triangle (report 4.1): Moller-Trumbore intersection; the normal is
// normalize((v1 - v0) x (v2 - v0)). Edges are stored, not vertices, because
// that is what the intersection test reads.
#pragma once

#include "core/hit.h"
#include "core/ray.h"

namespace fh {

template <typename T>
struct Triangle {
    Vec3<T> v0;
    Vec3<T> e1;      // v1 - v0
    Vec3<T> e2;      // v2 - v0
    Vec3<T> normal;  // unit; zero for a degenerate triangle, which never hits
    int material;

    static Triangle make(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, int material) {
        Triangle tri{a, b - a, c - a, Vec3<T>(0), material};
        const Vec3<T> n = glm::cross(tri.e1, tri.e2);
        const T len = glm::length(n);
        if (len > T(0) && std::isfinite(len)) tri.normal = n / len;
        return tri;
    }

    // Branch-free Moller-Trumbore. det == 0: the ray lies in the triangle's
    // plane, or the triangle has no area; there is no single crossing point
    // (the divisions then give inf or NaN, which the mask discards).
    FH_HOT_INLINE T intersect(const Ray<T>& ray, T t_min, T t_max) const {
        const Vec3<T> p = glm::cross(ray.direction, e2);
        const T det = glm::dot(e1, p);
        const T inv_det = T(1) / det;
        const Vec3<T> s = ray.origin - v0;
        const T u = glm::dot(s, p) * inv_det;
        const Vec3<T> q = glm::cross(s, e1);
        const T v = glm::dot(ray.direction, q) * inv_det;
        const T t = glm::dot(e2, q) * inv_det;
        const bool inside = (det != T(0)) & (u >= T(0)) & (v >= T(0)) & (u + v <= T(1));
        return (inside & (t > t_min) & (t < t_max)) ? t : kInfinity<T>;
    }

    Vec3<T> normal_at(const Vec3<T>&) const { return normal; }

    // Project onto the triangle's plane, so the error is relative to the
    // vertices' coordinates and not to the ray's travel.
    Vec3<T> point_at(const Ray<T>& ray, T t) const {
        const Vec3<T> p = ray.at(t);
        return p - glm::dot(normal, p - v0) * normal;
    }
};

}  // namespace fh
