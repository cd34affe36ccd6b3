// Triangle (report 4.1). The normal is the report's,
// normalize((v1 - v0) x (v2 - v0)); the intersection test is not the report's
// Moller-Trumbore but a watertight one (after Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2013), so that a ray can never slip between
// two triangles that share an edge or a vertex:
//
//  1. The vertices are taken relative to the ray's origin and projected along
//     the ray onto a plane across it (two unit vectors perpendicular to d;
//     the paper shears instead, which needs the ray's dominant axis and, in
//     a loop vectorised over rays, selects that cost more than the basis). A
//     shared vertex gets the same projected point in every triangle.
//  2. Edge functions U, V, W are the 2x2 determinants of consecutive projected
//     vertices, compensated by the products' exact rounding errors
//     (core/exact.h): their sign is never wrong, and a shared edge gets
//     exactly opposite values in its two triangles.
//  3. The ray hits when U, V, W have one sign, zeros included: a ray exactly
//     through an edge or vertex hits every triangle there (the nearest-hit
//     loop keeps one), never none. So among the triangles around any edge or
//     vertex of a closed mesh, a ray through it always finds one.
//
// t is the mix of the vertices' distances along the ray with U, V, W as
// barycentric weights (as in the paper): a ray passing the test hits between
// the nearest and the farthest vertex, however nearly it grazes the plane,
// so no ray slips through a face seen edge-on either. A degenerate triangle
// has a zero normal (make()) and never hits.
//
// Vertices 1 and 2 are v0 + e1 and v0 + e2: exact for coordinates on a common
// grid (the report's, any whole-number or short binary fractions), to one
// rounding otherwise (where a shared vertex could then differ by an ulp
// between two triangles). Everything is branch-free, so the batch loops of
// render/batch_intersect.h vectorise over rays.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/exact.h"
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

    // A triangle no wider than the rounding of its own coordinates -- its
    // height over the longest edge at most 32 epsilon of the largest
    // coordinate: no area, collinear vertices, a repeated vertex -- gets a
    // zero normal and never hits.
    static Triangle make(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, int material) {
        Triangle tri{a, b - a, c - a, Vec3<T>(0), material};
        const Vec3<T> n = glm::cross(tri.e1, tri.e2);
        const T len = glm::length(n);
        const T longest = std::max({glm::length(tri.e1), glm::length(tri.e2), glm::length(c - b)});
        const T size = std::max({max_abs_component(a), max_abs_component(b), max_abs_component(c)});
        const T eps = std::numeric_limits<T>::epsilon();
        if (len > T(32) * eps * size * longest && std::isfinite(len)) tri.normal = n / len;
        return tri;
    }

    bool degenerate() const { return normal == Vec3<T>(0); }

    // Nearest t in (t_min, t_max), or infinity.
    FH_HOT_INLINE T intersect(const Ray<T>& ray, T t_min, T t_max) const {
        const Vec3<T>& d = ray.direction;
        // Two unit vectors across the ray, e and g: Duff et al.'s branch-free
        // orthonormal basis ("Building an Orthonormal Basis, Revisited", JCGT
        // 2017), well conditioned for every direction.
        const T sg = std::copysign(T(1), d.z);
        const T k = T(-1) / (sg + d.z);
        const T m = d.x * d.y * k;
        const Vec3<T> e(T(1) + sg * d.x * d.x * k, sg * m, -sg * d.x);
        const Vec3<T> g(m, sg + d.y * d.y * k, -d.y);
        // Each vertex, from the ray's origin, projected along the ray onto the
        // plane of e and g (where the ray itself is the point (0, 0)). One
        // formula for every vertex, so a shared vertex lands on the same
        // point in each of its triangles.
        auto along = [](const Vec3<T>& p, const Vec3<T>& q) {
            return mul_add(p.x, q.x, mul_add(p.y, q.y, p.z * q.z));
        };
        const Vec3<T> a = v0 - ray.origin;
        const Vec3<T> b = (v0 + e1) - ray.origin;
        const Vec3<T> c = (v0 + e2) - ray.origin;
        const T ax2 = along(a, e), ay2 = along(a, g);
        const T bx2 = along(b, e), by2 = along(b, g);
        const T cx2 = along(c, e), cy2 = along(c, g);
        const T u = orientation(bx2, by2, cx2, cy2);
        const T v = orientation(cx2, cy2, ax2, ay2);
        const T w = orientation(ax2, ay2, bx2, by2);
        const bool outside = ((u < T(0)) | (v < T(0)) | (w < T(0))) & ((u > T(0)) | (v > T(0)) | (w > T(0)));
        // t: the vertices' distances along the ray, mixed with the edge
        // functions as barycentric weights. For a ray that passes the test it
        // lies between the nearest and the farthest vertex's, however nearly
        // the ray grazes the plane; det == 0 is a ray in the plane (the
        // projection has no area). A degenerate triangle (zero normal, see
        // make()) never hits.
        const T det = u + v + w;
        const T t = (u * glm::dot(a, d) + v * glm::dot(b, d) + w * glm::dot(c, d)) / det;
        const bool has_area = (normal.x != T(0)) | (normal.y != T(0)) | (normal.z != T(0));
        return (!outside & has_area & (det != T(0)) & (t > t_min) & (t < t_max)) ? t : kInfinity<T>;
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
