// A packet of rays against the flat scene: the nearest hit of each ray, or
// whether anything blocks it. The shapes' own intersect functions do the
// work (geometry/), each on the whole packet -- or, in a BVH leaf of
// triangles that fewer of the packet's rays reach than it holds, each of
// those rays on all of the leaf's triangles at once (TriangleBlock) -- so
// there is one copy of each formula; they skip their costly part when no
// ray can hit.
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
    Lanes<T> t;        // the nearest hit's distance; 0 or infinity where none
    LaneInts<T> prim;  // its primitive id (in its instance's mesh, if any), or kNoHit
};

// The primitives of a leaf the walk reports, tested against the rays:
//  - take(t, id): one primitive's t for the whole packet (id: its primitive id);
//  - take_one(lane, t, id): one ray's t for a block's columns, column j
//    being primitive id + j -- where fewer rays enter a leaf of triangles
//    than it holds, each is tested against all of them at once instead.
// limit() gives each ray's t_max as it stands. Either returns true to stop
// the leaf, and then so does this.
template <typename T, typename Limit, typename Take, typename TakeOne>
FH_HOT_INLINE bool test_leaf(const FlatGeometry<T>& geometry, const RayBasis<T>& basis, const WalkNode<T>& n,
                             const LaneInts<T>& entering, Limit&& limit, Take&& take, TakeOne&& take_one) {
    // A run of triangles: the same lines twice, on float's packed rows and
    // on double's blocks. Written once (a generic lambda taking either), the
    // float frames were 1-2.5% slower in 7 of 9 measurements (1,280 and
    // 1.3M triangles, the bunny; 3 interleaved rounds), double within noise;
    // written out, double's machine code is what it was before packed rows.
    if (n.triangle_run()) {
        const int id = geometry.ids.triangle(n.first_triangle());
        if constexpr (FlatGeometry<T>::kPackedRows) {
            const TriangleRows<T> block = geometry.packed_rows_of(n);
            if (count(entering) < n.count())
                return for_each_lane(entering, [&](int lane) FH_HOT_LAMBDA {
                    for (int j0 = 0; j0 < n.count(); j0 += kLanes<T>) {
                        const Lanes<T> t = block.intersect(basis, lane, j0, n.count(), T(0), splat_lane(limit(), lane));
                        if (take_one(lane, t, id + j0)) return true;
                    }
                    return false;
                });
            for (int j = 0; j < n.count(); ++j)
                if (take(block.intersect(basis, j, T(0), limit()), id + j)) return true;
            return false;
        } else {
            const TriangleBlock<T>& block = geometry.blocks[size_t(n.block())];
            if (count(entering) < n.count())
                return for_each_lane(entering, [&](int lane) FH_HOT_LAMBDA {
                    for (int j0 = 0; j0 < n.count(); j0 += kLanes<T>) {
                        const Lanes<T> t = block.intersect(basis, lane, j0, n.count(), T(0), splat_lane(limit(), lane));
                        if (take_one(lane, t, id + j0)) return true;
                    }
                    return false;
                });
            for (int j = 0; j < n.count(); ++j)
                if (take(block.intersect(basis, j, T(0), limit()), id + j)) return true;
            return false;
        }
    }
    for (int k = n.first_listed(); k < n.first_listed() + n.count(); ++k) {
        const int id = geometry.bvh.prims[size_t(k)];
        if (take(geometry.intersect(id, basis, T(0), limit()), id)) return true;
    }
    return false;
}

// subset: what a tile's camera rays can hit (render/tile_culling.h), tested
// one by one when it is short; nullptr or a long one: the BVH is walked.
// t_max: each ray's farthest distance (hits at it or past it are not
// found); 0 in the inactive lanes.
template <typename T>
FH_HOT_INLINE HitLanes<T> closest_hits_within(const FlatGeometry<T>& geometry, const RayPacket<T>& ray,
                                              const LaneInts<T>& active, const Lanes<T>& t_max,
                                              const PrimitiveSubset* subset = nullptr) {
    HitLanes<T> h{t_max, LaneInts<T>{} + kNoHit};
    // On a tie the lower primitive id wins, whatever order the BVH visits
    // them in: shapes before planes before triangles (render/primitive_ids.h), triangles in the flat
    // scene's order (the file's for small scenes, the leaves' for others).
    // So each BVH test looks a little past the nearest hit so far (`reach`),
    // and keep decides.
    auto keep = [&h](const Lanes<T>& t, int id) FH_HOT_LAMBDA {
        const LaneInts<T> nearer = (t < h.t) | ((t == h.t) & (h.prim > id));
        h.t = select(nearer, t, h.t);
        h.prim = select(nearer, LaneInts<T>{} + id, h.prim);
    };
    auto reach = [&h]() FH_HOT_LAMBDA { return h.t * (T(1) + std::numeric_limits<T>::epsilon()); };
    const PrimitiveIds& ids = geometry.ids;
    const int planes = int(geometry.planes.size());
    std::optional<RayBasis<T>> basis;  // built once a triangle is reached
    // A short list (a tile's, or a small scene's every primitive) is tested
    // one by one in increasing id order, so the first of equal hits is kept.
    const PrimitiveSubset& listed = subset && !subset->walk_bvh ? *subset : geometry.everything;
    if (!listed.walk_bvh) {
        const std::vector<int>& list = listed.prims;
        size_t k = 0;
        geometry.shapes.for_each_listed(list, k, ids.shapes, [&](const auto& s, int id) FH_HOT_LAMBDA {
            keep(s.intersect(ray, T(0), h.t), id);
            return false;
        });
        for (int p = 0; p < planes; ++p) keep(geometry.planes[size_t(p)].intersect(ray, T(0), h.t), ids.plane(p));
        if (k == list.size() || (geometry.small && none(geometry.few_triangles.reaches(ray) & (h.t > T(0))))) return h;
        const RayBasis<T> triangle_basis(ray);
        for (; k < list.size(); ++k)
            keep(geometry.triangles[size_t(ids.triangle_index(list[k]))].intersect(triangle_basis, T(0), h.t), list[k]);
        return h;
    }
    for (int p = 0; p < planes; ++p) keep(geometry.planes[size_t(p)].intersect(ray, T(0), reach()), ids.plane(p));
    // One ray's hits on a block's columns: the nearest, the first of equal
    // ones, goes through keep in that ray's lane alone (infinity, the others).
    auto keep_one = [&](int lane, const Lanes<T>& t, int id) FH_HOT_LAMBDA {
        T nearest = kInfinity<T>;
        int column = 0;
        for_each_lane(t < kInfinity<T>, [&](int j) FH_HOT_LAMBDA {
            if (t[j] < nearest) nearest = t[j], column = j;
            return false;
        });
        if (nearest < kInfinity<T>) {
            // Shading reads the hit's surface right after the walk; among a
            // million triangles that read missed the cache (7% of the trace's
            // samples in perf). Asked for now, it arrives while the walk goes
            // on. Both ends: a surface (40 bytes in float, 72 in double) may
            // straddle two cache lines.
            const PrimitiveSurface<T>* s = &geometry.surfaces[size_t(id + column)];
            __builtin_prefetch(s);
            __builtin_prefetch(reinterpret_cast<const char*>(s + 1) - 1);
            keep(select(lane_index<T>() == lane, splat(nearest), splat(kInfinity<T>)), id + column);
        }
        return false;
    };
    auto leaf = [&](const WalkNode<T>& n, const LaneInts<T>& entering) FH_HOT_LAMBDA {
        if (!basis) basis.emplace(ray);
        return test_leaf(
            geometry, *basis, n, entering, reach,
            [&](const Lanes<T>& t, int id) FH_HOT_LAMBDA {
                keep(t, id);
                return false;
            },
            keep_one);
    };

    for_each_leaf(geometry.walk_nodes, ray, active, h.t, leaf);
    return h;
}

template <typename T>
FH_HOT_INLINE HitLanes<T> closest_hits(const FlatGeometry<T>& geometry, const RayPacket<T>& ray,
                                       const LaneInts<T>& active, const PrimitiveSubset* subset = nullptr) {
    return closest_hits_within(geometry, ray, active, select(active, splat(kInfinity<T>), splat(T(0))), subset);
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
    const PrimitiveIds& ids = geometry.ids;
    std::optional<RayBasis<T>> basis;  // built once a leaf is reached
    auto leaf = [&](const WalkNode<T>& n, const LaneInts<T>& entering) FH_HOT_LAMBDA {
        if (!basis) basis.emplace(ray);
        return test_leaf(
            geometry, *basis, n, entering, [&limit]() FH_HOT_LAMBDA { return limit; },
            [&](const Lanes<T>& t, int) FH_HOT_LAMBDA { return block(t); },
            // block()'s body for one lane, written out: routing it through a
            // helper that block() shares gave the same frames but measured
            // 2-3% slower on the bunny in double, twice (GCC's inlining).
            [&](int lane, const Lanes<T>& t, int) FH_HOT_LAMBDA {
                if (none(t < kInfinity<T>)) return false;
                blocked |= lane_index<T>() == lane;
                limit = select(blocked, splat(T(0)), limit);
                return all(blocked | ~active);
            });
    };
    if (!geometry.everything.walk_bvh) {  // a small scene: every shape, the triangles behind their bound
        const std::vector<int>& list = geometry.everything.prims;
        size_t k = 0;
        if (geometry.shapes.for_each_listed(list, k, ids.shapes, [&](const auto& s, int) FH_HOT_LAMBDA {
                return block(s.intersect(ray, T(0), limit));
            }))
            return blocked;
        if (k == list.size() || none(geometry.few_triangles.reaches(ray) & (limit > T(0)))) return blocked;
        const RayBasis<T> triangle_basis(ray);
        for (; k < list.size(); ++k)
            if (block(geometry.triangles[size_t(ids.triangle_index(list[k]))].intersect(triangle_basis, T(0), limit)))
                return blocked;
        return blocked;
    }
    for_each_leaf(geometry.walk_nodes, ray, active, limit, leaf);
    return blocked;
}

// The nearest hit of one ray (tests, the viewer): a packet of one, so the
// same code as every other ray.
template <typename T>
Hit<T> closest_hit(const FlatGeometry<T>& geometry, const Ray<T>& ray) {
    const HitLanes<T> h = closest_hits(geometry, RayPacket<T>::splat(ray), first_lanes<T>(1));
    return h.prim[0] == kNoHit ? Hit<T>{} : Hit<T>{h.t[0], int(h.prim[0])};
}

}  // namespace fh
