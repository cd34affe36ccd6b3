// Packets through the two levels: the world's own primitives first
// (render/packet_intersect.h), then the instances the packet's rays reach
// in the top BVH, each entered by its inverse transform and walked with the
// same packet code in its mesh's space (render/instance_set.h). Ties go to
// the world's primitives, then to the lower instance, then to the lower
// primitive id within it, whatever order the walk finds them in.
#pragma once

#include <limits>

#include "render/instance_set.h"
#include "render/packet_intersect.h"
#include "render/ray_walk.h"

namespace fh {

// How far past the nearest hit so far an instance's mesh is searched: its
// distances are world ones times `scale` and back, two roundings each way.
template <typename T>
inline constexpr T kInstanceReach = T(1) + 4 * std::numeric_limits<T>::epsilon();

inline constexpr int kNoInstance = -1;  // a hit on the world's own primitives

// Up to this many rays of a packet entering an instance walk its mesh one
// by one (render/ray_walk.h), eight boxes a vector; more walk it together.
template <typename T>
inline constexpr int kAlone = 4;

// The nearest hits of the active rays, one ray at a time, as closest_hits_within gives them.
template <typename T>
FH_HOT_INLINE HitLanes<T> hits_one_by_one(const FlatGeometry<T>& mesh, const RayPacket<T>& ray,
                                          const LaneInts<T>& active, const Lanes<T>& t_max) {
    HitLanes<T> h{t_max, LaneInts<T>{} + kNoHit};
    const RayBasis<T> basis(ray);
    for_each_lane(active, [&](int lane) FH_HOT_LAMBDA {
        const RayHit<T> r = nearest_on_ray(mesh, basis, lane, t_max[lane]);
        if (r.prim != kNoHit) h.t[lane] = r.t, h.prim[lane] = r.prim;
        return false;
    });
    return h;
}

// Whether each active ray is blocked below its t_max, one ray at a time.
template <typename T>
FH_HOT_INLINE LaneInts<T> blocked_one_by_one(const FlatGeometry<T>& mesh, const RayPacket<T>& ray,
                                             const Lanes<T>& t_max, const LaneInts<T>& active) {
    LaneInts<T> blocked{};
    const RayBasis<T> basis(ray);
    for_each_lane(active, [&](int lane) FH_HOT_LAMBDA {
        if (blocked_on_ray(mesh, basis, lane, t_max[lane])) blocked[lane] = -1;
        return false;
    });
    return blocked;
}

// Hits on the set's instances nearer than h's (the world's), merged into
// h; returns each lane's instance, or kNoInstance.
template <typename T>
FH_HOT_INLINE LaneInts<T> closest_instance_hits(const InstanceSet<T>& set, const RayPacket<T>& ray,
                                                   const LaneInts<T>& active, HitLanes<T>& h) {
    LaneInts<T> on = LaneInts<T>{} + kNoInstance;
    for_each_leaf(set.walk_nodes, ray, active, h.t, [&](const WalkNode<T>& n, const LaneInts<T>& entering) FH_HOT_LAMBDA {
        for (int k = n.first_listed(); k < n.first_listed() + n.count(); ++k) {
            const int i = set.bvh.prims[size_t(k)];
            const FlatInstance<T>& instance = set.instances[size_t(i)];
            Lanes<T> scale;
            const RayPacket<T> local = instance.enter(ray, scale);
            const Lanes<T> limit = select(entering, h.t * scale * kInstanceReach<T>, splat(T(0)));
            const FlatGeometry<T>& mesh = *set.meshes[size_t(instance.mesh)];
            HitLanes<T> m = count(entering) <= kAlone<T> && !mesh.wide.empty()
                                ? hits_one_by_one(mesh, local, entering, limit)
                                : closest_hits_within(mesh, local, entering, limit);
            // (A BLENDed surface is hit, and seen through by the shader.)
            if (instance.cutout >= 0 && !set.cutouts[size_t(instance.cutout)].blend)
                m = past_cutouts(mesh, set.cutouts[size_t(instance.cutout)], local, entering, limit, m);
            const Lanes<T> t = m.t / scale;
            const LaneInts<T> tie = (t == h.t) & ((on > i) | ((on == i) & (h.prim > m.prim)));
            const LaneInts<T> nearer = (m.prim != kNoHit) & ((t < h.t) | tie);
            h.t = select(nearer, t, h.t);
            h.prim = select(nearer, m.prim, h.prim);
            on = select(nearer, LaneInts<T>{} + i, on);
        }
        return false;
    });
    return on;
}

// Per lane: some instance's surface lies in (0, t_max); t_max is 0 in the
// lanes to skip. kSeeThrough (a scene with see-through surfaces): those
// multiply each lane's *through by the light they let pass (light_through)
// instead, and block only the lanes left with none.
template <typename T, bool kSeeThrough = false>
FH_HOT_INLINE LaneInts<T> occluded_by_instances(const InstanceSet<T>& set, const RayPacket<T>& ray,
                                                Lanes<T> t_max, const LaneInts<T>& active,
                                                Lanes<T>* through = nullptr) {
    LaneInts<T> blocked = LaneInts<T>{};
    for_each_leaf(set.walk_nodes, ray, active, t_max, [&](const WalkNode<T>& n, const LaneInts<T>& entering) FH_HOT_LAMBDA {
        for (int k = n.first_listed(); k < n.first_listed() + n.count(); ++k) {
            const FlatInstance<T>& instance = set.instances[size_t(set.bvh.prims[size_t(k)])];
            Lanes<T> scale;
            const RayPacket<T> local = instance.enter(ray, scale);
            const LaneInts<T> asking = entering & (t_max > T(0));
            const FlatGeometry<T>& mesh = *set.meshes[size_t(instance.mesh)];
            const Cutout* cut = instance.cutout >= 0 ? &set.cutouts[size_t(instance.cutout)] : nullptr;
            if (kSeeThrough && cut && cut->blend) {
                *through = select(asking, *through * light_through(mesh, *cut, local, asking, t_max * scale), *through);
                blocked |= asking & (*through <= T(0));
            } else if (cut)  // blocked where the nearest point that is not a hole lies below t_max
                blocked |= asking & (past_cutouts(mesh, *cut, local, asking, t_max * scale,
                                                  closest_hits_within(mesh, local, asking, t_max * scale))
                                         .prim != kNoHit);
            else
                blocked |= count(asking) <= kAlone<T> && !mesh.wide.empty()
                               ? blocked_one_by_one(mesh, local, t_max * scale, asking)
                               : occluded(mesh, local, t_max * scale, asking);
            t_max = select(blocked, splat(T(0)), t_max);
            if (all(blocked | ~active)) return true;
        }
        return false;
    });
    return blocked;
}

// Both levels: the nearest hit of each active ray, and its instance.
template <typename T>
FH_HOT_INLINE HitLanes<T> closest_hits(const FlatGeometry<T>& world, const InstanceSet<T>* instances,
                                       const RayPacket<T>& ray, const LaneInts<T>& active, LaneInts<T>& instance,
                                       const PrimitiveSubset* subset = nullptr) {
    HitLanes<T> h = closest_hits(world, ray, active, subset);
    instance = instances ? closest_instance_hits(*instances, ray, active, h) : LaneInts<T>{} + kNoInstance;
    return h;
}

// Both levels: whether anything lies in (0, t_max) along each active ray.
// A yes or no: a see-through (BLEND) surface counts here as a cutout at
// alpha 0.5. The shader asks light_through_out_of_line instead where a
// scene has one, to dim the light by what it lets through.
template <typename T>
FH_HOT_INLINE LaneInts<T> occluded(const FlatGeometry<T>& world, const InstanceSet<T>* instances,
                                   const RayPacket<T>& ray, const Lanes<T>& t_max, const LaneInts<T>& active) {
    LaneInts<T> blocked = occluded(world, ray, t_max, active);
    if (!instances || all(blocked | ~active)) return blocked;
    return blocked | occluded_by_instances(*instances, ray, select(blocked | ~active, splat(T(0)), t_max),
                                           active & ~blocked);
}

// The same two as calls, for the shader's loop over scenes with instances
// (render/shading.h): one copy of each walk per scalar type, however many
// shader variants call them.
template <typename T>
__attribute__((noinline)) HitLanes<T> closest_hits_out_of_line(const FlatGeometry<T>& world,
                                                               const InstanceSet<T>* instances,
                                                               const RayPacket<T>& ray, const LaneInts<T>& active,
                                                               LaneInts<T>& instance, const PrimitiveSubset* subset) {
    return closest_hits(world, instances, ray, active, instance, subset);
}
template <typename T>
__attribute__((noinline)) LaneInts<T> occluded_out_of_line(const FlatGeometry<T>& world,
                                                           const InstanceSet<T>* instances, const RayPacket<T>& ray,
                                                           const Lanes<T>& t_max, const LaneInts<T>& active) {
    return occluded(world, instances, ray, t_max, active);
}

// Both levels, in a scene with see-through surfaces (FlatScene::blended):
// per lane the fraction of light that comes along each active ray from
// t_max -- 0 where something opaque lies in (0, t_max), else the product of
// (1 - alpha) over the see-through surfaces the ray crosses. A call, as the
// two above.
template <typename T>
__attribute__((noinline)) Lanes<T> light_through_out_of_line(const FlatGeometry<T>& world,
                                                             const InstanceSet<T>* instances, const RayPacket<T>& ray,
                                                             const Lanes<T>& t_max, const LaneInts<T>& active) {
    Lanes<T> through = splat(T(1));
    LaneInts<T> blocked = occluded(world, ray, t_max, active);
    if (instances && !all(blocked | ~active))
        blocked |= occluded_by_instances<T, true>(*instances, ray, select(blocked | ~active, splat(T(0)), t_max),
                                                  active & ~blocked, &through);
    return select(blocked, splat(T(0)), through);
}

// The nearest hit of one ray on both levels (tests, the viewer).
template <typename T>
Hit<T> closest_hit(const FlatGeometry<T>& world, const InstanceSet<T>* instances, const Ray<T>& ray) {
    LaneInts<T> instance;
    const HitLanes<T> h = closest_hits(world, instances, RayPacket<T>::splat(ray), first_lanes<T>(1), instance);
    if (h.prim[0] == kNoHit) return {};
    return {h.t[0], int(h.prim[0]), int(instance[0])};
}

}  // namespace fh
