// One ray of a packet through a flat geometry's eight-way tree
// (render/wide_bvh.h): its nearest hit, or whether anything blocks it. For
// the few rays of a packet that reach somewhere alone -- a far instance --
// where a packet walk would pay a whole vector per box for them. The leaves
// are tested as the packet walk's one-ray case tests them (a leaf's
// triangles in one vector, TriangleRows or TriangleBlock), and the nearest
// hit is chosen by the same rule: on a tie the lower primitive id.
#pragma once

#include <limits>

#include "render/packet_intersect.h"
#include "render/wide_bvh.h"

namespace fh {

// A leaf's triangles against ray `lane` of the basis's packet: each
// column's t below t_max (infinity where none), calling take(t_lanes, id of
// column 0) per vector of columns; for any other leaf, each primitive's t
// alone in column 0.
template <typename T, typename Take>
FH_HOT_INLINE bool test_leaf_for_ray(const FlatGeometry<T>& geometry, const RayBasis<T>& basis, int lane,
                                     const WalkNode<T>& n, T t_max, Take&& take) {
    if (n.triangle_run()) {
        const int id = geometry.ids.triangle(n.first_triangle());
        for (int j0 = 0; j0 < n.count(); j0 += kLanes<T>) {
            Lanes<T> t;
            if constexpr (FlatGeometry<T>::kPackedRows)
                t = geometry.packed_rows_of(n).intersect(basis, lane, j0, n.count(), T(0), splat(t_max));
            else
                t = geometry.blocks[size_t(n.block())].intersect(basis, lane, j0, n.count(), T(0), splat(t_max));
            if (take(t, id + j0)) return true;
        }
        return false;
    }
    for (int k = n.first_listed(); k < n.first_listed() + n.count(); ++k) {
        const int id = geometry.bvh.prims[size_t(k)];
        // This ray's t in column 0, as a run's first triangle's would be.
        Lanes<T> t = splat(kInfinity<T>);
        t[0] = geometry.intersect(id, basis, T(0), splat(t_max))[lane];
        if (take(t, id)) return true;
    }
    return false;
}

// The nearest hit of ray `lane` below t_max; prim kNoHit when none. Shapes and planes are not
// looked at: this is for meshes, whose primitives are all in the tree.
template <typename T>
struct RayHit {
    T t;
    int prim;
};
template <typename T>
FH_HOT_INLINE RayHit<T> nearest_on_ray(const FlatGeometry<T>& geometry, const RayBasis<T>& basis, int lane,
                                       T t_max) {
    RayHit<T> best{t_max, kNoHit};
    // As the packet walk's reach: a little past the nearest so far, so that
    // an equal hit of a lower id is still found.
    auto reach = [&best]() FH_HOT_LAMBDA { return best.t * (T(1) + std::numeric_limits<T>::epsilon()); };
    const Vec3<T> o = basis.ray.origin.lane(lane), d = basis.ray.direction.lane(lane);
    for_each_leaf_of_ray(geometry.wide, o, d, reach, [&](int w) FH_HOT_LAMBDA {
        return test_leaf_for_ray(geometry, basis, lane, geometry.walk_nodes[size_t(w)], reach(),
                                 [&](const Lanes<T>& t, int id) FH_HOT_LAMBDA {
            for_each_lane(t < kInfinity<T>, [&](int j) FH_HOT_LAMBDA {
                if (t[j] < best.t || (t[j] == best.t && best.prim != kNoHit && id + j < best.prim))
                    best = {t[j], id + j};
                return false;
            });
            return false;
        });
    });
    if (best.prim == kNoHit) best.t = kInfinity<T>;
    return best;
}

// Whether anything lies in (0, t_max) along ray `lane`.
template <typename T>
FH_HOT_INLINE bool blocked_on_ray(const FlatGeometry<T>& geometry, const RayBasis<T>& basis, int lane, T t_max) {
    bool blocked = false;
    const Vec3<T> o = basis.ray.origin.lane(lane), d = basis.ray.direction.lane(lane);
    for_each_leaf_of_ray(geometry.wide, o, d, [&]() FH_HOT_LAMBDA { return blocked ? T(0) : t_max; },
                         [&](int w) FH_HOT_LAMBDA {
        return test_leaf_for_ray(geometry, basis, lane, geometry.walk_nodes[size_t(w)], t_max,
                                 [&](const Lanes<T>& t, int) FH_HOT_LAMBDA {
            blocked = any(t < kInfinity<T>);
            return blocked;
        });
    });
    return blocked;
}

}  // namespace fh
