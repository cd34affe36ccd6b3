#include "render/bvh.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <limits>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "render/thread_pool.h"

namespace fh {

namespace {

constexpr int kBins = 16;
// Ranges smaller than a subtree's size (subtree_size) become subtrees built
// one per worker; larger ones are split on the calling thread, their
// binning spread over the pool when at least twice that size.
int subtree_size(int primitives, int workers) {
    // About 16 subtrees a worker, so that they share out evenly (a fixed
    // 32,768 left the bunny's second level binned on one thread and four
    // subtrees for two workers), but none so small that a task's overhead
    // shows, nor larger than a fixed size for big inputs.
    return std::clamp(primitives / (16 * workers), 4096, 32768);
}
// Past this depth splits are by count: the traversal's stack stays bounded
// whatever the input (coincident boxes give the heuristic nothing to split).
constexpr int kMaxSahDepth = 96;
// The cost of visiting a node against that of testing one primitive: a
// packet's watertight triangle test costs several box tests, but a leaf
// that one ray of a packet reaches tests all its triangles in one vector
// (geometry/triangle_block.h). Measured since that test, on the scaling
// family (1,280 to 1.3M triangles) and the bunny, with the leaf sizes the
// tracers ask for (render/flat_geometry.cpp): in float 8 beats 5, 6, 12 and
// 16; in double it is as fast as 4 and 6, or a little faster.
constexpr double kTraversalCost = 8.0;

// Four doubles rounded to the largest floats not above them: float(v),
// stepped down one float in the lanes where it rounded up. In vectors and
// masks, not branches: a refit rounds six values a leaf, half of them down a
// step, and libm's nextafter, then branches on the sign, then the branch on
// whether to step at all were a fifth, a third and a quarter of an instance
// set's update. (Written as scalar masks, GCC 12's SLP vectoriser at -O3
// for AVX-512 compiled this wrongly; as vectors there is nothing for it to
// vectorise.)
using Doubles4 = double __attribute__((vector_size(32)));
using Floats4 = float __attribute__((vector_size(16)));
using Ints4 = std::int32_t __attribute__((vector_size(16)));

Floats4 round_down(const Doubles4& v) {
    const Floats4 f = __builtin_convertvector(v, Floats4);
    // All ones where float(v) > v (a finite v beyond float: +inf, stepped
    // down to the largest float); never for an infinite or NaN v.
    const Ints4 rounded_up = __builtin_convertvector(__builtin_convertvector(f, Doubles4) > v, Ints4);
    // One step down: +x one less, -x (sign bit set) one more; +0 taken as
    // -0 first, whose step is the negative denormal.
    const Ints4 i = reinterpret_cast<Ints4>(f);
    const Ints4 signed_zero = i | ((i == 0) & std::numeric_limits<std::int32_t>::min());
    const Ints4 below = signed_zero - ((signed_zero >> 31) | 1);
    return reinterpret_cast<Floats4>((below & rounded_up) | (i & ~rounded_up));
}

// The box rounded outward to floats: its low corner down, and its high
// corner up, as minus the low corner of -box.
BvhNode node_with_box(const Aabb& b) {
    const Floats4 lo = round_down(Doubles4{b.lo.x, b.lo.y, b.lo.z, 0.0});
    const Floats4 hi = -round_down(Doubles4{-b.hi.x, -b.hi.y, -b.hi.z, 0.0});
    BvhNode n;
    for (int a = 0; a < 3; ++a) {
        n.lo[a] = lo[a];
        n.hi[a] = hi[a];
    }
    return n;
}

// The binning works in floats, four to a register (x, y, z and a spare
// lane): a primitive's box and centroid, and each bin's box. The heuristic
// only ranks the planes, so float's rounding can change which of two
// nearly equal ones wins, never a node's box (range_bounds, in double) --
// nor what a ray hits, which no tree changes.
typedef float Float4 __attribute__((vector_size(16)));
typedef std::int32_t Int4 __attribute__((vector_size(16)));

Float4 min4(Float4 a, Float4 b) { return b < a ? b : a; }
Float4 max4(Float4 a, Float4 b) { return a < b ? b : a; }
Float4 to_float4(const dvec3& v) { return Float4{float(v.x), float(v.y), float(v.z), 0.0f}; }

// A box in floats: a primitive's, a bin's, or a range's centroids'.
struct Box4 {
    Float4 lo = Float4{} + kInfinity<float>, hi = -lo;  // empty

    void grow(Float4 p) {
        lo = min4(lo, p);
        hi = max4(hi, p);
    }
    void grow(const Box4& b) {
        lo = min4(lo, b.lo);
        hi = max4(hi, b.hi);
    }
    // Half the surface area (0 for an empty box): what the heuristic compares.
    double half_area() const {
        if (!(lo[0] <= hi[0])) return 0;
        const double x = double(hi[0]) - lo[0], y = double(hi[1]) - lo[1], z = double(hi[2]) - lo[2];
        return x * y + y * z + z * x;
    }
    int widest_axis() const {
        const Float4 d = hi - lo;
        return d[0] >= d[1] && d[0] >= d[2] ? 0 : (d[1] >= d[2] ? 1 : 2);
    }
};

struct BinnedPrim {
    Box4 box;
    Float4 centroid;
};

struct Bins {
    Box4 box[3][kBins];
    int count[3][kBins] = {};

    void add(const Bins& o) {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < kBins; ++b) {
                box[a][b].grow(o.box[a][b]);
                count[a][b] += o.count[a][b];
            }
    }
};

// Which of the kBins bins along each axis a centroid falls in: the bins
// split [origin, origin + kBins / scale) evenly. The same floats bin a range
// and then partition it.
struct BinGrid {
    Float4 origin, scale;  // scale 0: an axis with no extent, not binned

    Int4 bins_of(Float4 centroid) const {
        // Clamped before the conversion, which leaves no value out of int's
        // range; NaN (a coordinate beyond float's range: inf - inf) to bin 0.
        const Float4 f = (centroid - origin) * scale;
        const Float4 low = f >= 0.0f ? f : Float4{};
        return __builtin_convertvector(low < float(kBins - 1) ? low : Float4{} + float(kBins - 1), Int4);
    }
};

struct Split {
    int axis = -1;
    int bin = 0;  // primitives in bins < bin go left
    double cost = kInfinity<double>;
    BinGrid grid;
};

// A subtree under construction: its nodes, and the slots of its parents
// still waiting for a subtree built elsewhere.
struct Pending {
    int begin, end;
    Aabb bounds;
    Box4 centroid_bounds;
    int depth;
    int parent, slot;  // nodes[parent].first (slot 0) or .second (slot 1)
};

class Builder {
public:
    Builder(const std::vector<Aabb>& boxes, const std::vector<BinnedPrim>& binned, BigArray<std::int32_t>& prims,
            int max_leaf, ThreadPool* pool)
        : boxes_(boxes), binned_(binned), prims_(prims), max_leaf_(max_leaf), pool_(pool),
          subtree_size_(subtree_size(int(prims.size()), pool ? pool->size() : 1)) {}

    // Builds [begin, end) into nodes (its root at the returned index); with
    // defer, ranges smaller than subtree_size_ go to `pending` instead.
    int build(BigArray<BvhNode>& nodes, int begin, int end, const Aabb& bounds, const Box4& centroids,
              int depth, bool defer, std::vector<Pending>* pending, int parent = -1, int slot = 0) {
        if (defer && end - begin < subtree_size_) {
            pending->push_back({begin, end, bounds, centroids, depth, parent, slot});
            return -1;
        }
        const int index = int(nodes.size());
        nodes.push_back(node_with_box(bounds));
        const int n = end - begin;
        nodes[size_t(index)].below = n;
        const Split split = depth < kMaxSahDepth ? best_split(begin, end, centroids, defer) : Split{};
        const double leaf_cost = double(n);
        const double split_cost =
            split.axis < 0 ? kInfinity<double> : kTraversalCost + split.cost / std::max(bounds.half_area(), 1e-300);
        if (n <= max_leaf_ && (split.axis < 0 || leaf_cost <= split_cost)) {
            nodes[size_t(index)].first = begin;
            nodes[size_t(index)].count = n;
            return index;
        }
        int mid = split.axis < 0 ? begin : partition(begin, end, split);
        if (mid == begin || mid == end) {  // no useful plane: halve by count
            mid = begin + n / 2;
            const int axis = centroids.widest_axis();
            std::nth_element(prims_.begin() + begin, prims_.begin() + mid, prims_.begin() + end, [&](int a, int b) {
                return binned_[size_t(a)].centroid[axis] < binned_[size_t(b)].centroid[axis];
            });
        }
        nodes[size_t(index)].axis = split.axis < 0 ? centroids.widest_axis() : split.axis;
        Aabb lb, rb;
        Box4 lc, rc;
        range_bounds(begin, mid, lb, lc);
        range_bounds(mid, end, rb, rc);
        const int left = build(nodes, begin, mid, lb, lc, depth + 1, defer, pending, index, 0);
        const int right = build(nodes, mid, end, rb, rc, depth + 1, defer, pending, index, 1);
        nodes[size_t(index)].first = left;
        nodes[size_t(index)].second = right;
        return index;
    }

    void range_bounds(int begin, int end, Aabb& bounds, Box4& centroids) const {
        for (int i = begin; i < end; ++i) {
            bounds.grow(boxes_[size_t(prims_[size_t(i)])]);
            centroids.grow(binned_[size_t(prims_[size_t(i)])].centroid);
        }
    }

private:
    void bin_range(int begin, int end, const BinGrid& grid, Bins& bins) const {
        for (int i = begin; i < end; ++i) {
            const BinnedPrim& p = binned_[size_t(prims_[size_t(i)])];
            const Int4 b = grid.bins_of(p.centroid);
            for (int a = 0; a < 3; ++a) {
                bins.box[a][b[a]].grow(p.box);
                ++bins.count[a][b[a]];
            }
        }
    }

    // The cheapest of the 3 x 15 bin boundaries; the binning of a large range
    // is spread over the pool.
    Split best_split(int begin, int end, const Box4& cb, bool parallel) const {
        BinGrid grid{cb.lo, Float4{}};
        const Float4 extent = cb.hi - cb.lo;
        for (int a = 0; a < 3; ++a) grid.scale[a] = extent[a] > 0 ? float(kBins) / extent[a] : 0.0f;
        Bins bins;
        const int n = end - begin;
        if (parallel && pool_ && n >= 2 * subtree_size_) {
            const int chunks = 4 * pool_->size();
            std::vector<Bins> partial(static_cast<size_t>(chunks));
            pool_->parallel_for(chunks, [&](int c, int) {
                bin_range(begin + int(std::int64_t(n) * c / chunks), begin + int(std::int64_t(n) * (c + 1) / chunks),
                          grid, partial[size_t(c)]);
            });
            for (const Bins& b : partial) bins.add(b);
        } else {
            bin_range(begin, end, grid, bins);
        }
        Split best;
        best.grid = grid;
        for (int a = 0; a < 3; ++a) {
            if (grid.scale[a] == 0) continue;
            // right[b]: the bins b .. kBins-1 together.
            double right_area[kBins];
            int right_count[kBins];
            Box4 acc;
            int count = 0;
            for (int b = kBins - 1; b > 0; --b) {
                acc.grow(bins.box[a][b]);
                count += bins.count[a][b];
                right_area[b] = acc.half_area();
                right_count[b] = count;
            }
            acc = Box4{};
            count = 0;
            for (int b = 1; b < kBins; ++b) {
                acc.grow(bins.box[a][b - 1]);
                count += bins.count[a][b - 1];
                if (count == 0 || right_count[b] == 0) continue;
                const double cost = acc.half_area() * count + right_area[b] * right_count[b];
                if (cost < best.cost) best = {a, b, cost, grid};
            }
        }
        return best;
    }

    int partition(int begin, int end, const Split& s) const {
        const auto mid = std::partition(prims_.begin() + begin, prims_.begin() + end, [&](int p) {
            return s.grid.bins_of(binned_[size_t(p)].centroid)[s.axis] < s.bin;
        });
        return int(mid - prims_.begin());
    }

    const std::vector<Aabb>& boxes_;
    const std::vector<BinnedPrim>& binned_;
    BigArray<std::int32_t>& prims_;
    int max_leaf_;
    ThreadPool* pool_;
    int subtree_size_;
};

}  // namespace

Bvh build_bvh(const std::vector<Aabb>& boxes, ThreadPool* pool, int max_leaf) {
    if (max_leaf < 1 || max_leaf > kMaxLeafSize)
        throw std::invalid_argument("build_bvh: max_leaf " + std::to_string(max_leaf) + " is not in 1.." +
                                    std::to_string(kMaxLeafSize));
    const auto start = std::chrono::steady_clock::now();
    Bvh bvh;
    std::vector<BinnedPrim> binned(boxes.size());
    for (size_t i = 0; i < boxes.size(); ++i) {
        binned[i] = {{to_float4(boxes[i].lo), to_float4(boxes[i].hi)}, to_float4(boxes[i].center())};
        if (!boxes[i].empty()) bvh.prims.push_back(std::int32_t(i));
    }
    if (bvh.prims.empty()) return bvh;
    Builder builder(boxes, binned, bvh.prims, max_leaf, pool);
    Aabb bounds;
    Box4 centroid_bounds;
    builder.range_bounds(0, int(bvh.prims.size()), bounds, centroid_bounds);

    // The top of the tree here, the subtrees below subtree_size on the pool,
    // each into nodes of its own, then appended.
    std::vector<Pending> pending;
    builder.build(bvh.nodes, 0, int(bvh.prims.size()), bounds, centroid_bounds, 0, true, &pending);
    std::vector<BigArray<BvhNode>> subtrees(pending.size());
    auto build_subtree = [&](int k, int) {
        const Pending& p = pending[size_t(k)];
        builder.build(subtrees[size_t(k)], p.begin, p.end, p.bounds, p.centroid_bounds, p.depth, false, nullptr);
    };
    if (pool && pending.size() > 1) pool->parallel_for(int(pending.size()), build_subtree);
    else for (int k = 0; k < int(pending.size()); ++k) build_subtree(k, 0);
    for (size_t k = 0; k < pending.size(); ++k) {
        const int offset = int(bvh.nodes.size());
        for (BvhNode n : subtrees[k]) {
            if (!n.leaf()) {
                n.first += offset;
                n.second += offset;
            }
            bvh.nodes.push_back(n);
        }
        if (pending[k].parent >= 0) {
            BvhNode& parent = bvh.nodes[size_t(pending[k].parent)];
            (pending[k].slot == 0 ? parent.first : parent.second) = offset;
        }
    }
    bvh.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return bvh;
}

void refit_bvh(Bvh& bvh, const std::vector<Aabb>& boxes) {
    const auto start = std::chrono::steady_clock::now();
    // Children follow their parent: from the back, both are done first. Only
    // a leaf's box is rounded to float; an inner node's is its children's
    // float boxes joined, which is the same value as rounding the join of
    // their double boxes (rounding down is monotone: the least of the
    // rounded values is the rounded least). Only the sign of a zero bound
    // can differ from a build's (a tiny double and a -0 both ending as a
    // float zero), which no box test tells apart.
    for (size_t k = bvh.nodes.size(); k-- > 0;) {
        BvhNode& n = bvh.nodes[k];
        if (n.leaf()) {
            Aabb b;
            for (int i = n.first; i < n.first + n.count; ++i) b.grow(boxes[size_t(bvh.prims[size_t(i)])]);
            const BvhNode rounded = node_with_box(b);
            std::copy(rounded.lo, rounded.lo + 3, n.lo);
            std::copy(rounded.hi, rounded.hi + 3, n.hi);
        } else {
            const BvhNode& a = bvh.nodes[size_t(n.first)];
            const BvhNode& b = bvh.nodes[size_t(n.second)];
            for (int axis = 0; axis < 3; ++axis) {
                n.lo[axis] = std::min(a.lo[axis], b.lo[axis]);
                n.hi[axis] = std::max(a.hi[axis], b.hi[axis]);
            }
        }
    }
    bvh.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace fh
