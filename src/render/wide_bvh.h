// The BVH again, eight children a node, for rays that travel alone. A packet
// walk (render/bvh_traversal.h) tests one box for all its rays at once: the
// right thing while they stay together, but a packet's few rays that reach a
// far instance -- three of sixteen on average in a forest of 10,000 -- each
// pay a whole vector per box. One ray against eight boxes per vector pays
// for boxes instead. Collapsed from the binary tree, its leaves are the binary
// tree's leaves (WalkNode, with their triangle blocks), so both walks find
// the same triangles with the same tests.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include "core/big_array.h"
#include "core/packet.h"
#include "render/bvh.h"

namespace fh {

inline constexpr int kWideChildren = 8;

struct WideNode {
    // The children's boxes, axis by axis (rounded outward, as BvhNode's); an
    // empty slot's are NaN, which no ray enters (every comparison fails).
    float lo[3][kWideChildren];
    float hi[3][kWideChildren];
    // >= 0: a wide node; < 0: ~ the walk node of a leaf (FlatGeometry::walk_nodes).
    std::int32_t child[kWideChildren];
};

struct WideBvh {
    BigArray<WideNode> nodes;  // nodes[0]: the root (empty: no BVH, or a root that is a leaf)
    std::int32_t root_leaf = -1;  // a tree of one leaf: its walk node (and no nodes)

    bool empty() const { return nodes.empty() && root_leaf < 0; }
};

// The eight-way tree over `bvh`; walk_of[k]: the walk node of BVH node k
// (walk_nodes_of's `from`, inverted), for the leaves. A node takes its
// children's children while it has room, the largest box first.
WideBvh collapse(const Bvh& bvh, const std::vector<std::int32_t>& walk_of);

// Eight values of T in one vector (AVX-512: one register for double, half
// of one for float), for one ray against a node's eight boxes.
template <typename T>
struct Eight;
template <>
struct Eight<float> {
    typedef float Values __attribute__((vector_size(32)));
    typedef std::int32_t Ints __attribute__((vector_size(32)));
};
template <>
struct Eight<double> {
    typedef double Values __attribute__((vector_size(64)));
    typedef std::int64_t Ints __attribute__((vector_size(64)));
};

// Calls leaf(walk_node) for the leaves one ray enters, nearest first by
// where the ray enters their boxes; t_max() gives its limit as it stands
// (the leaves shorten it). The box test is the packet walk's, conservative
// the same way (render/bvh_traversal.h: tiny direction components, the far
// distance enlarged by 8 ulps). leaf returns true to end the walk.
template <typename T, typename Limit, typename Leaf>
FH_HOT_INLINE void for_each_leaf_of_ray(const WideBvh& wide, const Vec3<T>& origin, const Vec3<T>& direction,
                                        Limit&& t_max, Leaf&& leaf) {
    if (wide.root_leaf >= 0) {
        leaf(wide.root_leaf);
        return;
    }
    if (wide.nodes.empty()) return;
    using V = typename Eight<T>::Values;
    constexpr T tiny = std::numeric_limits<T>::min() * T(1) / std::numeric_limits<T>::epsilon();
    auto inverse_of = [&](T d) { return T(1) / (std::abs(d) < tiny ? std::copysign(tiny, d) : d); };
    const V ox = V{} + origin.x, oy = V{} + origin.y, oz = V{} + origin.z;
    const V ix = V{} + inverse_of(direction.x), iy = V{} + inverse_of(direction.y), iz = V{} + inverse_of(direction.z);
    const T grow = T(1) + 8 * std::numeric_limits<T>::epsilon();
    // (Outputs, not returned vectors, here and below: a 64-byte vector
    // returned without AVX-512 draws GCC's ABI warning, even inlined.)
    auto load = [](const float (&row)[kWideChildren], V& v) FH_HOT_LAMBDA {
        for (int c = 0; c < kWideChildren; ++c) v[c] = T(row[c]);
    };
    struct Entry {
        std::int32_t node;
        T near;
    };
    Entry stack[kWideChildren * 160];  // at most 7 more a level, the binary depth bounded by 160
    int top = 0;
    stack[top++] = {0, T(0)};
    while (top > 0) {
        const Entry e = stack[--top];
        if (e.near > t_max()) continue;  // the ray found something nearer meanwhile
        if (e.node < 0) {
            if (leaf(~e.node)) return;
            continue;
        }
        const WideNode& n = wide.nodes[size_t(e.node)];
        V lo[3], hi[3];
        for (int a = 0; a < 3; ++a) load(n.lo[a], lo[a]), load(n.hi[a], hi[a]);
        const V x0 = (lo[0] - ox) * ix, x1 = (hi[0] - ox) * ix;
        const V y0 = (lo[1] - oy) * iy, y1 = (hi[1] - oy) * iy;
        const V z0 = (lo[2] - oz) * iz, z1 = (hi[2] - oz) * iz;
        // The packet walk's min and max, written out (a tie or NaN keeps the
        // first): near = max(min x, min y, min z, 0), far = min(max x, max y, max z).
        const V nx = x1 < x0 ? x1 : x0, ny = y1 < y0 ? y1 : y0, nz = z1 < z0 ? z1 : z0;
        const V fx = x0 < x1 ? x1 : x0, fy = y0 < y1 ? y1 : y0, fz = z0 < z1 ? z1 : z0;
        const V nxy = nx < ny ? ny : nx, nz0 = nz < V{} ? V{} : nz;
        const V near = nxy < nz0 ? nz0 : nxy;
        const V fxy = fy < fx ? fy : fx;
        const V far = (fz < fxy ? fz : fxy) * grow;
        const T limit = t_max();
        const auto enter = (near <= far) & (near <= limit) & (limit > T(0));
        // The children entered, pushed farthest first so the nearest is
        // next: by their bits (one loop per child entered, not per slot),
        // each slid into place among those pushed from this node.
        unsigned bits = 0;
        for (int c = 0; c < kWideChildren; ++c) bits |= unsigned(enter[c] != 0) << c;
        const int first = top;
        for (; bits != 0; bits &= bits - 1) {
            const int c = __builtin_ctz(bits);
            const Entry child{n.child[c], near[c]};
            int k = top++;
            for (; k > first && stack[k - 1].near < child.near; --k) stack[k] = stack[k - 1];
            stack[k] = child;
        }
    }
}

}  // namespace fh
