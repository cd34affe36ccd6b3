// Triangle (report 4.1). The normal is the report's,
// normalize((v1 - v0) x (v2 - v0)); the intersection test is not the report's
// Moller-Trumbore but a watertight one (after Woop, Benthin and Wald, "Watertight
// Ray/Triangle Intersection", JCGT 2013), so that a ray can never slip between
// two triangles that share an edge or a vertex:
//
//  1. The vertices are taken relative to the ray's origin and projected along
//     the ray onto a plane across it (two unit vectors perpendicular to d;
//     the paper shears instead, which needs the ray's dominant axis: on a
//     packet, per-lane selects that cost more than the basis). A shared
//     vertex gets the same projected point in every triangle.
//  2. Edge functions U, V, W are the 2x2 determinants of consecutive projected
//     vertices, each a rounded difference of rounded products (core/exact.h):
//     their sign is never wrong (at worst zero within an ulp of zero), and a
//     shared edge gets exactly opposite values in its two triangles.
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
// Everything runs on a packet of rays (core/packet.h); the basis across each
// ray depends only on the ray, so a packet computes it once (RayBasis) for
// every triangle it meets. The same formula also runs on one ray against a
// BVH leaf's triangles, a triangle per lane (geometry/triangle_block.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/exact.h"
#include "core/packet.h"
#include "geometry/surface.h"

namespace fh {

// A packet of rays with two unit vectors across each, e and g: Duff et al.'s
// branch-free orthonormal basis ("Building an Orthonormal Basis, Revisited",
// JCGT 2017), well conditioned for every direction.
template <typename T>
struct RayBasis {
    const RayPacket<T>& ray;  // built and used within one pass over a packet: never outlives it
    Vec3Lanes<T> e, g;

    explicit FH_HOT_INLINE RayBasis(const RayPacket<T>& r) : ray(r) {
        const Vec3Lanes<T>& d = r.direction;
        const Lanes<T> sg = copysign(splat(T(1)), d.z);
        const Lanes<T> k = T(-1) / (sg + d.z);
        const Lanes<T> m = d.x * d.y * k;
        e = {T(1) + sg * d.x * d.x * k, sg * m, -sg * d.x};
        g = {m, sg + d.y * d.y * k, -d.y};
    }
};

// The test itself, lane by lane: a, b, c are a triangle's vertices taken
// from a ray's origin, d the ray's direction, e and g its basis. Lanes hold
// rays (Triangle::intersect: one triangle, a packet of rays) or triangles
// (TriangleBlock: one ray, a block of triangles) -- the same operations on
// each lane either way, so the same bits. t in (t_min, t_max), or infinity.
template <typename T>
FH_HOT_INLINE Lanes<T> watertight_distance(const Vec3Lanes<T>& a, const Vec3Lanes<T>& b, const Vec3Lanes<T>& c,
                                           const Vec3Lanes<T>& d, const Vec3Lanes<T>& e, const Vec3Lanes<T>& g,
                                           T t_min, const Lanes<T>& t_max) {
    const Lanes<T> no_hit = splat(kInfinity<T>);
    // Each vertex projected along the ray onto the plane of e and g (where
    // the ray itself is the point (0, 0)). One formula for every vertex, so
    // a shared vertex lands on the same point in each of its triangles.
    auto along = [](const Vec3Lanes<T>& p, const Vec3Lanes<T>& q) FH_HOT_LAMBDA {
        return mul_add(p.x, q.x, mul_add(p.y, q.y, p.z * q.z));
    };
    const Lanes<T> ax2 = along(a, e), ay2 = along(a, g);
    const Lanes<T> bx2 = along(b, e), by2 = along(b, g);
    const Lanes<T> cx2 = along(c, e), cy2 = along(c, g);
    const Lanes<T> u = orientation(bx2, by2, cx2, cy2);
    const Lanes<T> v = orientation(cx2, cy2, ax2, ay2);
    const Lanes<T> w = orientation(ax2, ay2, bx2, by2);
    const LaneInts<T> outside = ((u < T(0)) | (v < T(0)) | (w < T(0))) &
                                ((u > T(0)) | (v > T(0)) | (w > T(0)));
    // No lane passes: skip the division.
    if (all(outside | (t_max <= t_min))) return no_hit;
    // t: the vertices' distances along the ray, mixed with the edge functions
    // as barycentric weights. For a ray that passes the test it lies between
    // the nearest and the farthest vertex's, however nearly the ray grazes
    // the plane; det == 0 is a ray in the plane (the projection has no area).
    const Lanes<T> det = u + v + w;
    const Lanes<T> t = (u * dot(a, d) + v * dot(b, d) + w * dot(c, d)) / det;
    return select(~outside & (det != T(0)) & (t > t_min) & (t < t_max), t, no_hit);
}

template <typename T>
struct Triangle {
    Vec3<T> v0, v1, v2;
    Vec3<T> normal;  // unit; zero for a degenerate triangle, which never hits
    int material;

    // A triangle no wider than the rounding of its own coordinates -- its
    // height over the longest edge at most 32 epsilon of the largest
    // coordinate: no area, collinear vertices, a repeated vertex -- gets a
    // zero normal and never hits.
    static Triangle make(const Vec3<T>& a, const Vec3<T>& b, const Vec3<T>& c, int material) {
        Triangle tri{a, b, c, Vec3<T>(0), material};
        const Vec3<T> e1 = b - a, e2 = c - a;
        const Vec3<T> n = glm::cross(e1, e2);
        const T len = glm::length(n);
        const T longest = std::max({glm::length(e1), glm::length(e2), glm::length(c - b)});
        const T size = std::max({max_abs_component(a), max_abs_component(b), max_abs_component(c)});
        const T eps = std::numeric_limits<T>::epsilon();
        if (len > T(32) * eps * size * longest && std::isfinite(len)) tri.normal = n / len;
        return tri;
    }

    bool degenerate() const { return normal == Vec3<T>(0); }

    // Nearest t in (t_min, t_max) for each ray of a packet, or infinity.
    FH_HOT_INLINE Lanes<T> intersect(const RayBasis<T>& rays, T t_min, Lanes<T> t_max) const {
        if (degenerate()) return splat(kInfinity<T>);
        const Vec3Lanes<T>& o = rays.ray.origin;
        return watertight_distance<T>(v0 - o, v1 - o, v2 - o, rays.ray.direction, rays.e, rays.g, t_min, t_max);
    }

    // One ray: the packet formula with that ray in every lane.
    T intersect(const Ray<T>& ray, T t_min, T t_max) const {
        const RayPacket<T> packet = RayPacket<T>::splat(ray);
        return intersect(RayBasis<T>(packet), t_min, splat(t_max))[0];
    }

    PrimitiveSurface<T> surface() const { return PrimitiveSurface<T>::flat_through(v0, normal, material); }
};

}  // namespace fh
