// A bounding volume hierarchy over the scene's bounded primitives (every
// primitive but the planes, which are unbounded): binary nodes with boxes,
// split by the surface area heuristic over 16 bins, built on the thread pool.
// Boxes are floats rounded outward from the double bounds, so a box always
// holds its primitives in either tracer precision, at half the memory.
// Traversal (render/bvh_traversal.h) walks it with whole packets of rays.
#pragma once

#include <cstdint>
#include <vector>

#include "core/big_array.h"
#include "geometry/aabb.h"

namespace fh {

class ThreadPool;

struct BvhNode {
    float lo[3], hi[3];  // rounded outward
    // Leaf (count > 0): primitives Bvh::prims[first .. first + count).
    // Inner (count == 0): children `first` and `second`.
    std::int32_t first = 0;
    std::int32_t second = 0;
    std::int32_t count = 0;
    std::int32_t axis = 0;  // inner: the split axis, for front-to-back order
    std::int32_t below = 0;  // how many primitives the subtree holds (a tile's culling gives up early)

    bool leaf() const { return count > 0; }
};

struct Bvh {
    // nodes[0] is the root (absent: nothing bounded); a node's children
    // always come after it.
    BigArray<BvhNode> nodes;
    BigArray<std::int32_t> prims;  // the input's indices, in leaf order
    double build_ms = 0;

    bool empty() const { return nodes.empty(); }
};

// The largest leaf any build may make (the walk keeps a leaf's count in 4
// bits, render/bvh_traversal.h).
inline constexpr int kMaxLeafSize = 15;

// The hierarchy over boxes[0 .. n). Boxes that are empty (a degenerate input)
// are left out. pool == nullptr builds on the calling thread. A leaf holds
// at most max_leaf (1 .. kMaxLeafSize) primitives, and fewer where
// splitting costs less than it saves.
Bvh build_bvh(const std::vector<Aabb>& boxes, ThreadPool* pool, int max_leaf);

// The same tree over new boxes of the same primitives (they moved): every
// node's box recomputed bottom-up, the topology kept. Cheaper than a build
// by far; the tree only gets worse for the traversal as the primitives
// stray from where it was built. An input's box must not have become empty.
void refit_bvh(Bvh& bvh, const std::vector<Aabb>& boxes);

}  // namespace fh
