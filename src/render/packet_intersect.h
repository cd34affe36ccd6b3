// A packet of rays against the flat scene: the nearest hit of each ray, or
// whether anything blocks it. The shapes' own intersect functions do the
// work (geometry/), each on the whole packet, so there is one copy of each
// formula; they skip their costly part when no ray of the packet can hit.
//
// Lanes that are not active ask for nothing: they get an interval (0, 0),
// which no shape can hit, so they neither count nor keep a packet from
// skipping a shape.
#pragma once

#include <optional>

#include "render/flat_scene.h"

namespace fh {

template <typename T>
struct HitLanes {
    Lanes<T> t;           // the nearest hit's distance; 0 or infinity where none
    LaneInts<T> prim;     // its primitive id, or kNoHit
};

// subset: the spheres and clusters that can be hit (FlatScene::everything,
// or a tile's: render/tile_culling.h).
template <typename T>
FH_HOT_INLINE HitLanes<T> closest_hits(const FlatScene<T>& scene, const RayPacket<T>& ray,
                                         const LaneInts<T>& active, const PrimitiveSubset& subset) {
    HitLanes<T> h{select(active, splat(kInfinity<T>), splat(T(0))), LaneInts<T>{} + kNoHit};
    auto keep = [&h](const Lanes<T>& t, int id) FH_HOT_LAMBDA {
        const LaneInts<T> nearer = t < h.t;
        h.t = select(nearer, t, h.t);
        h.prim = select(nearer, LaneInts<T>{} + id, h.prim);
    };
    const int spheres = int(scene.spheres.size()), planes = int(scene.planes.size());
    for (const int i : subset.spheres) keep(scene.spheres[size_t(i)].intersect(ray, T(0), h.t), i);
    for (int p = 0; p < planes; ++p) keep(scene.planes[size_t(p)].intersect(ray, T(0), h.t), spheres + p);
    std::optional<RayBasis<T>> basis;  // built once a cluster is reached
    for (const int i : subset.clusters) {
        const TriangleCluster<T>& c = scene.clusters[size_t(i)];
        if (none(c.reaches(ray) & (h.t > T(0)))) continue;
        if (!basis) basis.emplace(ray);
        for (int k = c.first; k < c.first + c.count; ++k)
            keep(scene.triangles[size_t(k)].intersect(*basis, T(0), h.t), spheres + planes + k);
    }
    return h;
}

// Per lane: some surface lies in (0, t_max) along the ray. Stops as soon as
// every active ray is blocked.
template <typename T>
FH_HOT_INLINE LaneInts<T> occluded(const FlatScene<T>& scene, const RayPacket<T>& ray,
                                   const Lanes<T>& t_max, const LaneInts<T>& active) {
    LaneInts<T> blocked = LaneInts<T>{};
    Lanes<T> limit = select(active, t_max, splat(T(0)));  // 0 once a lane is blocked
    auto block = [&](const Lanes<T>& t) FH_HOT_LAMBDA {
        blocked |= t < limit;
        limit = select(blocked, splat(T(0)), limit);
        return all(blocked | ~active);
    };
    for (const Sphere<T>& s : scene.spheres)
        if (block(s.intersect(ray, T(0), limit))) return blocked;
    for (const Plane<T>& p : scene.planes)
        if (block(p.intersect(ray, T(0), limit))) return blocked;
    std::optional<RayBasis<T>> basis;  // built once a cluster is reached
    for (const TriangleCluster<T>& c : scene.clusters) {
        if (none(c.reaches(ray) & (limit > T(0)))) continue;
        if (!basis) basis.emplace(ray);
        for (int k = c.first; k < c.first + c.count; ++k)
            if (block(scene.triangles[size_t(k)].intersect(*basis, T(0), limit))) return blocked;
    }
    return blocked;
}

// The nearest hit of one ray (tests, the viewer): a packet of one, so the
// same code as every other ray.
template <typename T>
Hit<T> closest_hit(const FlatScene<T>& scene, const Ray<T>& ray) {
    const HitLanes<T> h = closest_hits(scene, RayPacket<T>::splat(ray), first_lanes<T>(1), scene.everything);
    return h.prim[0] == kNoHit ? Hit<T>{} : scene.hit_of(h.t[0], int(h.prim[0]));
}

}  // namespace fh
