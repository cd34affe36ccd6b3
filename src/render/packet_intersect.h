// A packet of rays against the flat scene: the nearest hit of each ray, or
// whether anything blocks it. The shapes' own intersect functions do the
// work (geometry/), each on the whole packet, so there is one copy of each
// formula; they skip their costly part when no ray of the packet can hit.
//
// Lanes that are not active ask for nothing: they get an interval (0, 0),
// which no shape can hit, so they neither count nor keep a packet from
// skipping a shape.
#pragma once

#include <limits>
#include <optional>

#include "render/bvh_traversal.h"
#include "render/flat_geometry.h"

namespace fh {

template <typename T>
struct HitLanes {
    Lanes<T> t;           // the nearest hit's distance; 0 or infinity where none
    LaneInts<T> prim;     // its primitive id, or kNoHit
};

// The primitives of a leaf the walk reports (a: see WalkNode), by kind:
// sphere(i) for spheres[i], triangle(k) for triangles[k]. Either returns
// true to stop the leaf, and then so does this.
template <typename T, typename SphereFn, typename TriangleFn>
FH_HOT_INLINE bool for_each_in_leaf(const FlatGeometry<T>& geometry, int a, int count, SphereFn&& sphere,
                                    TriangleFn&& triangle) {
    if (a >= 0) {  // a run of triangles
        for (int k = a; k < a + count; ++k)
            if (triangle(k)) return true;
        return false;
    }
    const int spheres = int(geometry.spheres.size());
    for (int k = ~a; k < ~a + count; ++k) {
        const int i = geometry.bvh.prims[size_t(k)];
        if (i < spheres ? sphere(i) : triangle(i - spheres)) return true;
    }
    return false;
}

// subset: what a tile's camera rays can hit (render/tile_culling.h), tested
// one by one when it is short; nullptr or a long one: the BVH is walked.
template <typename T>
FH_HOT_INLINE HitLanes<T> closest_hits(const FlatGeometry<T>& geometry, const RayPacket<T>& ray,
                                         const LaneInts<T>& active, const PrimitiveSubset* subset = nullptr) {
    HitLanes<T> h{select(active, splat(kInfinity<T>), splat(T(0))), LaneInts<T>{} + kNoHit};
    // On a tie the lower primitive id wins, whatever order the BVH visits
    // them in: spheres before planes before triangles, triangles in the flat
    // scene's order (the file's for small scenes, the leaves' for others).
    // So each BVH test looks a little past the nearest hit so far (`reach`),
    // and keep decides.
    auto keep = [&h](const Lanes<T>& t, int id) FH_HOT_LAMBDA {
        const LaneInts<T> nearer = (t < h.t) | ((t == h.t) & (h.prim > id));
        h.t = select(nearer, t, h.t);
        h.prim = select(nearer, LaneInts<T>{} + id, h.prim);
    };
    auto reach = [&h]() FH_HOT_LAMBDA { return h.t * (T(1) + std::numeric_limits<T>::epsilon()); };
    const int spheres = int(geometry.spheres.size()), planes = int(geometry.planes.size());
    std::optional<RayBasis<T>> basis;  // built once a triangle is reached
    // A short list (a tile's, or a small scene's every primitive) is tested
    // one by one in increasing id order, so the first of equal hits is kept.
    const PrimitiveSubset& listed = subset && !subset->walk_bvh ? *subset : geometry.everything;
    if (!listed.walk_bvh) {
        const std::vector<int>& list = listed.prims;
        size_t k = 0;
        for (; k < list.size() && list[k] < spheres; ++k)
            keep(geometry.spheres[size_t(list[k])].intersect(ray, T(0), h.t), list[k]);
        for (int p = 0; p < planes; ++p) keep(geometry.planes[size_t(p)].intersect(ray, T(0), h.t), spheres + p);
        if (k == list.size() || (geometry.small && none(geometry.few_triangles.reaches(ray) & (h.t > T(0))))) return h;
        const RayBasis<T> triangle_basis(ray);
        for (; k < list.size(); ++k)
            keep(geometry.triangles[size_t(list[k] - spheres)].intersect(triangle_basis, T(0), h.t), planes + list[k]);
        return h;
    }
    for (int p = 0; p < planes; ++p) keep(geometry.planes[size_t(p)].intersect(ray, T(0), reach()), spheres + p);
    auto test_leaf = [&](int a, int count) FH_HOT_LAMBDA {
        if (!basis) basis.emplace(ray);
        return for_each_in_leaf(
            geometry, a, count,
            [&](int i) FH_HOT_LAMBDA {
                keep(geometry.spheres[size_t(i)].intersect(ray, T(0), reach()), i);
                return false;
            },
            [&](int k) FH_HOT_LAMBDA {
                keep(geometry.triangles[size_t(k)].intersect(*basis, T(0), reach()), spheres + planes + k);
                return false;
            });
    };

    for_each_leaf(geometry.walk_nodes, ray, active, h.t, test_leaf);
    return h;
}

// Per lane: some surface lies in (0, t_max) along the ray. Stops as soon as
// every active ray is blocked.
template <typename T>
FH_HOT_INLINE LaneInts<T> occluded(const FlatGeometry<T>& geometry, const RayPacket<T>& ray,
                                   const Lanes<T>& t_max, const LaneInts<T>& active) {
    LaneInts<T> blocked = LaneInts<T>{};
    Lanes<T> limit = select(active, t_max, splat(T(0)));  // 0 once a lane is blocked
    auto block = [&](const Lanes<T>& t) FH_HOT_LAMBDA {
        blocked |= t < limit;
        limit = select(blocked, splat(T(0)), limit);
        return all(blocked | ~active);
    };
    for (const Plane<T>& p : geometry.planes)
        if (block(p.intersect(ray, T(0), limit))) return blocked;
    const int spheres = int(geometry.spheres.size());
    std::optional<RayBasis<T>> basis;  // built once a triangle is reached
    auto test_leaf = [&](int a, int count) FH_HOT_LAMBDA {
        if (!basis) basis.emplace(ray);
        return for_each_in_leaf(
            geometry, a, count,
            [&](int i) FH_HOT_LAMBDA { return block(geometry.spheres[size_t(i)].intersect(ray, T(0), limit)); },
            [&](int k) FH_HOT_LAMBDA { return block(geometry.triangles[size_t(k)].intersect(*basis, T(0), limit)); });
    };
    if (!geometry.everything.walk_bvh) {  // a small scene: every sphere, the triangles behind their bound
        const std::vector<int>& list = geometry.everything.prims;
        size_t k = 0;
        for (; k < list.size() && list[k] < spheres; ++k)
            if (block(geometry.spheres[size_t(list[k])].intersect(ray, T(0), limit))) return blocked;
        if (k == list.size() || none(geometry.few_triangles.reaches(ray) & (limit > T(0)))) return blocked;
        const RayBasis<T> triangle_basis(ray);
        for (; k < list.size(); ++k)
            if (block(geometry.triangles[size_t(list[k] - spheres)].intersect(triangle_basis, T(0), limit)))
                return blocked;
        return blocked;
    }
    for_each_leaf(geometry.walk_nodes, ray, active, limit, test_leaf);
    return blocked;
}

// The nearest hit of one ray (tests, the viewer): a packet of one, so the
// same code as every other ray.
template <typename T>
Hit<T> closest_hit(const FlatGeometry<T>& geometry, const Ray<T>& ray) {
    const HitLanes<T> h = closest_hits(geometry, RayPacket<T>::splat(ray), first_lanes<T>(1));
    return h.prim[0] == kNoHit ? Hit<T>{} : geometry.hit_of(h.t[0], int(h.prim[0]));
}

}  // namespace fh
