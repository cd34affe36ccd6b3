// Walking the BVH (render/bvh.h) with a whole packet: a node is entered when
// any ray of the packet meets its box nearer than that ray's current limit
// (its nearest hit so far, or a shadow ray's light), children nearest first
// along the split axis as the packet's first active ray sees it. The box
// test is the slab test, made conservative: zero direction components are
// replaced by a tiny one of the same sign (no 0 * inf), and the far
// distance is enlarged by 8 ulps, more than the rounding of the test
// (Ize, "Robust BVH Ray Traversal", JCGT 2013), so rounding never culls a
// box a ray really enters.
#pragma once

#include <limits>
#include <vector>

#include "core/packet.h"
#include "render/bvh.h"
#include "render/primitive_ids.h"

namespace fh {

// The packet's rays as the box test reads them.
template <typename T>
struct BoxRays {
    Vec3Lanes<T> origin, inverse;
    bool negative[3];  // the first active ray goes toward -x, -y, -z

    FH_HOT_INLINE BoxRays(const RayPacket<T>& ray, const LaneInts<T>& active) : origin(ray.origin) {
        constexpr T tiny = std::numeric_limits<T>::min() * T(1) / std::numeric_limits<T>::epsilon();
        auto inverse_of = [](const Lanes<T>& d) FH_HOT_LAMBDA {
            return T(1) / select(abs(d) < tiny, copysign(splat(tiny), d), d);
        };
        inverse = {inverse_of(ray.direction.x), inverse_of(ray.direction.y), inverse_of(ray.direction.z)};
        int lane = 0;
        while (lane < kLanes<T> - 1 && active[lane] == 0) ++lane;
        negative[0] = ray.direction.x[lane] < 0;
        negative[1] = ray.direction.y[lane] < 0;
        negative[2] = ray.direction.z[lane] < 0;
    }
};

// A node's box in the tracer's type: no conversion in the walk.
template <typename T>
struct NodeBox {
    T lo[3], hi[3];
};

// A node as the walk reads it: its box and what it holds in one piece --
// 32 bytes in float, 64 in double, so a visit reads one cache line, not a
// box from one array and the node from another. The nodes are in
// depth-first order, so an inner node's first child is the next node.
// What it holds takes two integers; the accessors name their meanings.
template <typename T>
struct alignas(8 * sizeof(T)) WalkNode {
    NodeBox<T> box;

    bool leaf() const { return packed_ > 0; }

    // An inner node: the second child (the first is the next node), and the
    // split axis, along which the second child holds the larger coordinates.
    int second_child() const { return index_; }
    int axis() const { return -1 - packed_; }

    // A leaf holds count() primitives, either
    int count() const { return packed_ & 15; }
    //  - a run of triangles, first_triangle() .. + count() - 1 (triangle
    //    indices, renumbered in leaf order: nothing to look up between a node
    //    and its triangles), also held column by column (FlatGeometry::blocks
    //    [block()] in double, packed_rows in float);
    bool triangle_run() const { return index_ >= 0; }
    int first_triangle() const { return index_; }
    int block() const { return packed_ >> 4; }
    //  - or any primitives, listed by id in Bvh::prims from first_listed() on.
    int first_listed() const { return ~index_; }

    static WalkNode inner(const NodeBox<T>& box, int axis) { return {box, 0, -1 - axis}; }
    static WalkNode run(const NodeBox<T>& box, int first_triangle, int count, int block) {
        return {box, first_triangle, count + 16 * block};
    }
    static WalkNode listed(const NodeBox<T>& box, int first, int count) { return {box, ~first, count}; }
    void set_second_child(int node) { index_ = node; }

    // inner: the second child; a run: its first triangle (>= 0); listed: ~its first entry (< 0).
    std::int32_t index_;
    // inner: -1 - the axis (< 0); a leaf: count + 16 block (> 0).
    std::int32_t packed_;
};
static_assert(kMaxLeafSize < 16, "a leaf's count takes 4 bits of WalkNode::packed_");

// The walk's copy of a hierarchy over primitive ids (empty for an empty one).
// The leaves that hold a run of triangles number their blocks 0, 1, ... in
// order. from: receives, for each walk node, the BVH node it copies (so a
// refit can update the boxes alone: refit_walk_boxes).
template <typename T>
BigArray<WalkNode<T>> walk_nodes_of(const Bvh& bvh, const PrimitiveIds& ids,
                                    std::vector<std::int32_t>* from = nullptr) {
    BigArray<WalkNode<T>> out;
    int blocks = 0;
    if (bvh.empty()) return out;
    out.reserve(bvh.nodes.size());
    // Depth first: a node, then its first child's subtree, then its second's,
    // whose index is written into the node once known.
    struct Todo {
        int node, parent;  // parent: whose second child this is, or -1
    };
    std::vector<Todo> todo{{0, -1}};
    while (!todo.empty()) {
        const Todo t = todo.back();
        todo.pop_back();
        const int index = int(out.size());
        if (t.parent >= 0) out[size_t(t.parent)].set_second_child(index);
        const BvhNode& n = bvh.nodes[size_t(t.node)];
        if (from) from->push_back(t.node);
        const NodeBox<T> box{{T(n.lo[0]), T(n.lo[1]), T(n.lo[2])}, {T(n.hi[0]), T(n.hi[1]), T(n.hi[2])}};
        if (n.leaf()) {
            const std::int32_t* p = &bvh.prims[size_t(n.first)];
            bool run = ids.is_triangle(p[0]);
            for (int j = 1; run && j < n.count; ++j) run = p[j] == p[0] + j;
            out.push_back(run ? WalkNode<T>::run(box, ids.triangle_index(p[0]), n.count, blocks++)
                              : WalkNode<T>::listed(box, n.first, n.count));
        } else {
            out.push_back(WalkNode<T>::inner(box, n.axis));
            todo.push_back({n.second, index});
            todo.push_back({n.first, -1});
        }
    }
    return out;
}

// After refit_bvh: each walk node's box anew from the BVH node it copies
// (walk_nodes_of's `from`); the rest of the walk is the same.
template <typename T>
void refit_walk_boxes(BigArray<WalkNode<T>>& walk, const Bvh& bvh, const std::vector<std::int32_t>& from) {
    for (size_t k = 0; k < walk.size(); ++k) {
        const BvhNode& n = bvh.nodes[size_t(from[k])];
        walk[k].box = {{T(n.lo[0]), T(n.lo[1]), T(n.lo[2])}, {T(n.hi[0]), T(n.hi[1]), T(n.hi[2])}};
    }
}

// Per lane: the ray meets the node's box at a distance in [0, t_max].
// Lanes with t_max <= 0 (inactive, or blocked shadow rays) never do.
template <typename T>
FH_HOT_INLINE LaneInts<T> enters(const NodeBox<T>& n, const BoxRays<T>& r, const Lanes<T>& t_max) {
    const Lanes<T> x0 = (n.lo[0] - r.origin.x) * r.inverse.x, x1 = (n.hi[0] - r.origin.x) * r.inverse.x;
    const Lanes<T> y0 = (n.lo[1] - r.origin.y) * r.inverse.y, y1 = (n.hi[1] - r.origin.y) * r.inverse.y;
    const Lanes<T> z0 = (n.lo[2] - r.origin.z) * r.inverse.z, z1 = (n.hi[2] - r.origin.z) * r.inverse.z;
    const Lanes<T> near = max(max(min(x0, x1), min(y0, y1)), max(min(z0, z1), splat(T(0))));
    const Lanes<T> far =
        min(min(max(x0, x1), max(y0, y1)), max(z0, z1)) * (T(1) + 8 * std::numeric_limits<T>::epsilon());
    return (near <= far) & (near <= t_max) & (t_max > T(0));
}

// Calls leaf(node, entering) for the leaves the packet enters, nearest
// first, with the lanes that enter it; t_max is read anew at every node
// (the leaves shorten it). leaf returns true to end the walk (every shadow
// ray blocked).
template <typename T, typename Leaf>
FH_HOT_INLINE void for_each_leaf(const BigArray<WalkNode<T>>& nodes, const RayPacket<T>& ray,
                                 const LaneInts<T>& active, const Lanes<T>& t_max, Leaf&& leaf) {
    if (nodes.empty()) return;
    const BoxRays<T> rays(ray, active);
    // Depth is bounded by the builder (SAH to depth 96, then halving).
    int stack[160];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const int i = stack[--top];
        const WalkNode<T>& n = nodes[size_t(i)];
        const LaneInts<T> entering = enters(n.box, rays, t_max);
        if (none(entering)) continue;
        if (n.leaf()) {
            if (leaf(n, entering)) return;
            continue;
        }
        // Children split along the axis: the second holds the larger coordinates.
        const bool second_nearer = rays.negative[n.axis()];
        stack[top++] = second_nearer ? i + 1 : n.second_child();  // visited second
        stack[top++] = second_nearer ? n.second_child() : i + 1;
    }
}

}  // namespace fh
