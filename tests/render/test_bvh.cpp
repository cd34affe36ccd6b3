// The BVH finds exactly what a loop over every primitive finds: the same
// nearest hit (t and primitive, bit for bit) for a million random rays on
// random soups of spheres and triangles, the same answer for shadow rays,
// in float and double; and no ray slips through a closed mesh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <random>
#include <string>

#include "geometry/icosphere.h"
#include "render/bvh.h"
#include "render/effect_plan.h"
#include "render/flat_scene.h"
#include "render/packet_intersect.h"
#include "render/thread_pool.h"
#include "robustness/robust_util.h"
#include "sanitizer_build.h"

namespace fh {
namespace {

// A soup in the cube [-5, 5]^3: triangles of random size (from slivers to
// a fifth of the cube) and spheres, with one material.
Scene soup(int triangles, int spheres, unsigned seed) {
    Scene s;
    robust::add_material(s, "m", robust::material(dvec3(200), 0.2, 0.8, 0, 1));
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-5, 5), size(0.01, 2);
    auto point = [&] { return dvec3(u(rng), u(rng), u(rng)); };
    for (int i = 0; i < triangles; ++i) {
        const dvec3 a = point(), d = size(rng) * glm::normalize(point()), e = size(rng) * glm::normalize(point());
        s.triangles.push_back(Triangle<double>::make(a, a + d, a + e, 0));
    }
    for (int i = 0; i < spheres; ++i) s.spheres().push_back({point(), size(rng) * 0.5, 0});
    return s;
}

// The nearest hits by testing every primitive, lowest id first on a tie:
// the rule closest_hits keeps, whatever order its walk takes.
template <typename T>
HitLanes<T> brute_force_hits(const FlatGeometry<T>& f, const RayPacket<T>& ray, const LaneInts<T>& active) {
    HitLanes<T> h{select(active, splat(kInfinity<T>), splat(T(0))), LaneInts<T>{} + kNoHit};
    auto keep = [&](const Lanes<T>& t, int id) {
        const LaneInts<T> nearer = (t < h.t) | ((t == h.t) & (h.prim > id));
        h.t = select(nearer, t, h.t);
        h.prim = select(nearer, LaneInts<T>{} + id, h.prim);
    };
    const RayBasis<T> basis(ray);
    const int ns = int(f.spheres().size()), np = int(f.planes.size());
    for (int i = 0; i < ns; ++i)
        keep(f.spheres()[size_t(i)].intersect(ray, T(0), h.t * (T(1) + std::numeric_limits<T>::epsilon())), i);
    for (int i = 0; i < np; ++i)
        keep(f.planes[size_t(i)].intersect(ray, T(0), h.t * (T(1) + std::numeric_limits<T>::epsilon())), ns + i);
    for (int i = 0; i < int(f.triangles.size()); ++i)
        keep(f.triangles[size_t(i)].intersect(basis, T(0), h.t * (T(1) + std::numeric_limits<T>::epsilon())),
             ns + np + i);
    return h;
}

template <typename T>
LaneInts<T> brute_force_blocked(const FlatGeometry<T>& f, const RayPacket<T>& ray, const Lanes<T>& t_max,
                                const LaneInts<T>& active) {
    LaneInts<T> blocked{};
    const Lanes<T> limit = select(active, t_max, splat(T(0)));
    const RayBasis<T> basis(ray);
    for (const auto& s : f.spheres()) blocked |= s.intersect(ray, T(0), limit) < limit;
    for (const auto& p : f.planes) blocked |= p.intersect(ray, T(0), limit) < limit;
    for (const auto& t : f.triangles) blocked |= t.intersect(basis, T(0), limit) < limit;
    return blocked & active;
}

template <typename T>
class BvhAgainstBruteForce : public ::testing::Test {};
using Precisions = ::testing::Types<float, double>;
TYPED_TEST_SUITE(BvhAgainstBruteForce, Precisions);

// Rays of three kinds: from anywhere in any direction (mostly misses), aimed
// at a random point of a random triangle, and aimed exactly at a triangle's
// vertex or edge midpoint (where triangles tie).
template <typename T>
RayPacket<T> random_scene_packet(const Scene& s, std::mt19937_64& rng, int kind) {
    std::uniform_real_distribution<double> u(-8, 8), w(0, 1);
    std::uniform_int_distribution<size_t> pick(0, s.triangles.size() - 1);
    RayPacket<T> p;
    for (int l = 0; l < kLanes<T>; ++l) {
        const dvec3 o(u(rng), u(rng), u(rng));
        dvec3 target(u(rng), u(rng), u(rng));
        const Triangle<double>& t = s.triangles[pick(rng)];
        if (kind == 1) {
            double a = w(rng), b = w(rng);
            if (a + b > 1) a = 1 - a, b = 1 - b;
            target = t.v0 + a * (t.v1 - t.v0) + b * (t.v2 - t.v0);
        } else if (kind == 2) {
            const dvec3 corners[] = {t.v0, t.v1, t.v2, 0.5 * (t.v0 + t.v1), 0.5 * (t.v1 + t.v2)};
            target = corners[pick(rng) % 5];
        }
        const Vec3<T> d = glm::normalize(Vec3<T>(target) - Vec3<T>(o));
        p.origin.x[l] = T(o.x), p.origin.y[l] = T(o.y), p.origin.z[l] = T(o.z);
        p.direction.x[l] = d.x, p.direction.y[l] = d.y, p.direction.z[l] = d.z;
    }
    return p;
}

// Random packets aimed at `s` through the BVH walk and through the brute
// force: how many rays hit, and how many nearest hits and shadow answers
// differ.
struct Tally {
    long hits = 0, mismatches = 0, shadow_mismatches = 0;
};
template <typename T>
Tally against_brute_force(const FlatGeometry<T>& f, const Scene& s, unsigned seed, int rays) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> len(0, 20);
    Tally n;
    for (int k = 0; k < rays / kLanes<T>; ++k) {
        const RayPacket<T> ray = random_scene_packet<T>(s, rng, k % 3);
        const LaneInts<T> active = first_lanes<T>(kLanes<T> - (k % 4 == 0 ? 1 : 0));
        const HitLanes<T> bvh = closest_hits(f, ray, active);
        const HitLanes<T> all = brute_force_hits(f, ray, active);
        Lanes<T> t_max;
        for (int l = 0; l < kLanes<T>; ++l) t_max[l] = T(len(rng));
        const LaneInts<T> blocked = occluded(f, ray, t_max, active) & active;
        const LaneInts<T> expected = brute_force_blocked(f, ray, t_max, active);
        for (int l = 0; l < kLanes<T>; ++l) {
            n.hits += all.prim[l] != kNoHit;
            n.mismatches += bvh.prim[l] != all.prim[l] || (all.prim[l] != kNoHit && bvh.t[l] != all.t[l]);
            n.shadow_mismatches += (blocked[l] != 0) != (expected[l] != 0);
        }
    }
    return n;
}

// Shapes moved after the build (a movie's frame): the refitted tree keeps
// its topology and still finds exactly the brute-force hits.
TYPED_TEST(BvhAgainstBruteForce, RefitAfterMovingKeepsTheTreeAndTheHits) {
    using T = TypeParam;
    const Scene s = soup(400, 40, 7);
    Scene moved = s;
    for (size_t i = 0; i < moved.triangles.size(); ++i) {
        const Triangle<double>& t = moved.triangles[i];
        const dvec3 d(std::sin(double(i)), std::cos(double(i)), 0.5);  // each its own way, up to ~1.5
        moved.triangles[i] = Triangle<double>::make(t.v0 + d, t.v1 + d, t.v2 + d, t.material);
    }
    for (auto& sphere : moved.spheres()) sphere.center = -sphere.center;
    const auto built = FlatGeometry<T>::build(s);
    const auto f = built.refit(moved);
    ASSERT_EQ(f.bvh.nodes.size(), built.bvh.nodes.size());
    EXPECT_EQ(f.bvh.prims, built.bvh.prims);  // the same tree, refitted
    const Tally n = against_brute_force(f, moved, 13, 1 << 16);
    EXPECT_EQ(n.mismatches, 0);
    EXPECT_EQ(n.shadow_mismatches, 0);
    EXPECT_GT(n.hits, (1 << 16) / 4);
}

TYPED_TEST(BvhAgainstBruteForce, SameNearestHitAndSameShadowsForAMillionRays) {
    using T = TypeParam;
  // A soup walked through the BVH, and one small enough to be tested whole.
  for (const auto& [triangles, spheres] : {std::pair{400, 40}, std::pair{10, 4}}) {
    const Scene s = soup(triangles, spheres, 7);
    const auto f = FlatGeometry<T>::build(s);
    ASSERT_FALSE(f.bvh.empty());
    EXPECT_EQ(f.small, triangles + spheres <= int(kMaxSubset));
    const int rays = kSanitized ? 1 << 16 : 1 << 20;
    const Tally n = against_brute_force(f, s, 11, rays);
    EXPECT_EQ(n.mismatches, 0) << triangles;
    EXPECT_EQ(n.shadow_mismatches, 0) << triangles;
    EXPECT_GT(n.hits, rays / 4) << triangles;  // the aimed rays hit: the test has teeth
  }
}

// A unit icosphere subdivided three times (1280 triangles, closed): every
// ray from inside it, and every ray aimed from outside at one of its
// vertices or edge midpoints (where the ray meets several triangles at
// once), must hit it.
TYPED_TEST(BvhAgainstBruteForce, NoRayLeaksThroughAClosedMesh) {
    using T = TypeParam;
    Scene s;
    robust::add_material(s, "m", robust::material(dvec3(200), 0.2, 0.8, 0, 1));
    s.triangles = icosphere(3, 1.0, 0);
    ASSERT_EQ(s.triangles.size(), 1280u);
    const auto f = FlatGeometry<T>::build(s);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<size_t> pick(0, s.triangles.size() - 1);
    const int packets = (kSanitized ? 1 << 14 : 1 << 17) / kLanes<T>;
    long leaks = 0;
    for (int k = 0; k < packets; ++k) {
        RayPacket<T> p;
        for (int l = 0; l < kLanes<T>; ++l) {
            dvec3 o, target;
            if (k % 2 == 0) {  // from inside, any direction
                o = 0.5 * dvec3(u(rng), u(rng), u(rng));
                target = o + dvec3(u(rng), u(rng), u(rng));
            } else {  // from outside, at a vertex or an edge's midpoint on the near side
                const Triangle<double>& t = s.triangles[pick(rng)];
                target = (l % 2) ? t.v0 : 0.5 * (t.v0 + t.v1);
                // Not from the side: a ray grazing a convex mesh at a vertex
                // of its outline may rightly miss it.
                o = 3.0 * glm::normalize(target + 0.5 * glm::normalize(dvec3(u(rng), u(rng), u(rng))));
            }
            const Vec3<T> d = glm::normalize(Vec3<T>(target) - Vec3<T>(o));
            p.origin.x[l] = T(o.x), p.origin.y[l] = T(o.y), p.origin.z[l] = T(o.z);
            p.direction.x[l] = d.x, p.direction.y[l] = d.y, p.direction.z[l] = d.z;
        }
        const HitLanes<T> h = closest_hits(f, p, first_lanes<T>(kLanes<T>));
        const LaneInts<T> blocked = occluded(f, p, splat(T(10)), first_lanes<T>(kLanes<T>));
        for (int l = 0; l < kLanes<T>; ++l) leaks += (h.prim[l] == kNoHit) + (blocked[l] == 0);
    }
    EXPECT_EQ(leaks, 0);
}

// What every tree must be, checked against its input: every box is in
// exactly one leaf of at most max_leaf, each leaf's box holds its boxes, and
// every node's box holds its children's. Returns the largest leaf.
int expect_a_valid_tree(const std::vector<Aabb>& boxes, const Bvh& bvh, int max_leaf, const std::string& what) {
    const size_t n = boxes.size();
    std::vector<int> seen(n, 0);
    auto inside = [](const BvhNode& outer, const Aabb& b) {
        for (int a = 0; a < 3; ++a)
            if (!(outer.lo[a] <= b.lo[a] && b.hi[a] <= outer.hi[a])) return false;
        return true;
    };
    long bad = 0;
    int largest = 0;
    for (const BvhNode& node : bvh.nodes) {
        if (node.leaf()) {
            EXPECT_LE(node.count, max_leaf) << what;
            largest = std::max(largest, node.count);
            for (int k = node.first; k < node.first + node.count; ++k) {
                const int i = bvh.prims[size_t(k)];
                ++seen[size_t(i)];
                bad += !inside(node, boxes[size_t(i)]);
            }
        } else {
            for (const int c : {node.first, node.second}) {
                const BvhNode& child = bvh.nodes[size_t(c)];
                Aabb cb{{child.lo[0], child.lo[1], child.lo[2]}, {child.hi[0], child.hi[1], child.hi[2]}};
                bad += !inside(node, cb);
            }
        }
    }
    EXPECT_EQ(bad, 0) << what;
    EXPECT_EQ(size_t(std::count(seen.begin(), seen.end(), 1)), n) << what;
    return largest;
}

// Built on the pool or alone, from a million boxes or a few.
TEST(Bvh, EveryBoxInOneLeafInsideEveryBoxAboveIt) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-100, 100), size(0, 3);
    ThreadPool pool(2);
    for (const int n : {1, 7, 1000, kSanitized ? 40000 : 200000}) {
        std::vector<Aabb> boxes(static_cast<size_t>(n));
        for (Aabb& b : boxes) {
            b.grow(dvec3(u(rng), u(rng), u(rng)));
            b.grow(b.lo + dvec3(size(rng), size(rng), size(rng)));
        }
        for (ThreadPool* p : {static_cast<ThreadPool*>(nullptr), &pool}) {
            const int max_leaf = p ? kMaxLeafSize : 8;  // the double tracer's and the largest
            const int largest = expect_a_valid_tree(boxes, build_bvh(boxes, p, max_leaf), max_leaf, std::to_string(n));
            if (n == 7) EXPECT_EQ(largest, 7) << "seven boxes: one leaf, not worth a split";
        }
    }
}

// The split search bins in floats (render/bvh.cpp): boxes beyond float's
// range (their centroids infinite there, some differences NaN), and boxes
// whose centroids float cannot tell apart, still make a valid tree of
// leaves no larger than asked -- only the planes' ranking is in float.
TEST(Bvh, BoxesBeyondFloatOrTooCloseForItStillMakeAValidTree) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    ThreadPool pool(2);
    std::vector<Aabb> huge, close;
    for (int i = 0; i < 3000; ++i) {
        const double scale = i % 3 == 0 ? 1e300 : i % 3 == 1 ? -1e300 : 10;
        Aabb b;
        b.grow(scale * dvec3(u(rng), u(rng), u(rng)));
        b.grow(b.lo + dvec3(1));
        huge.push_back(b);
        // 1e7 plus a few thousandths: one float, three thousand doubles.
        Aabb c;
        c.grow(dvec3(1e7) + 1e-6 * dvec3(i, -i, 2 * i));
        c.grow(c.lo + dvec3(1e-7));
        close.push_back(c);
    }
    for (ThreadPool* p : {static_cast<ThreadPool*>(nullptr), &pool}) {
        expect_a_valid_tree(huge, build_bvh(huge, p, 8), 8, "beyond float");
        expect_a_valid_tree(close, build_bvh(close, p, 8), 8, "too close for float");
    }
}

// The tightest float box around a subtree's boxes, by libm: the largest
// float at most each low bound, the smallest at least each high bound.
float float_at_most(double v) {
    const float f = float(v);
    return double(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float float_at_least(double v) { return -float_at_most(-v); }

// Every node's box, built or refitted, is its boxes' double box rounded out
// to the nearest floats, not one float further: bounds that are floats
// already (zeros of both signs among them), that round either way, that
// float cannot hold (beyond its range, below its smallest denormal).
TEST(Bvh, EveryNodeIsItsBoxesRoundedOutToTheNearestFloats) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> u(-1, 1);
    const double values[] = {0.0, -0.0, 1e-320, -1e-320, 1e39, -1e39, 0.1, -0.1, 1.0, 3.0, -3.0};
    auto bound = [&](int kind) {
        switch (kind % 4) {
        case 0: return values[rng() % std::size(values)];
        case 1: return double(float(8 * u(rng)));
        case 2: return 8 * u(rng);
        default: return std::ldexp(u(rng), int(rng() % 300) - 150);
        }
    };
    auto random_boxes = [&] {
        std::vector<Aabb> boxes(500);
        for (Aabb& b : boxes)
            for (int a = 0; a < 3; ++a) {
                const double x = bound(int(rng() % 4)), y = bound(int(rng() % 4));
                b.lo[a] = std::min(x, y);
                b.hi[a] = std::max(x, y);
            }
        return boxes;
    };
    auto expect_tight = [](const Bvh& bvh, const std::vector<Aabb>& boxes, const char* what) {
        std::vector<Aabb> exact(bvh.nodes.size());
        long loose = 0;
        for (size_t k = bvh.nodes.size(); k-- > 0;) {
            const BvhNode& n = bvh.nodes[k];
            if (n.leaf())
                for (int i = n.first; i < n.first + n.count; ++i) exact[k].grow(boxes[size_t(bvh.prims[size_t(i)])]);
            else
                exact[k] = exact[size_t(n.first)], exact[k].grow(exact[size_t(n.second)]);
            // Values, not bits: a refit joins float zeros, whose sign
            // may differ from the rounded double join's (render/bvh.cpp).
            for (int a = 0; a < 3; ++a)
                loose += n.lo[a] != float_at_most(exact[k].lo[a]) || n.hi[a] != float_at_least(exact[k].hi[a]);
        }
        EXPECT_EQ(loose, 0) << what;
    };
    const std::vector<Aabb> boxes = random_boxes();
    Bvh bvh = build_bvh(boxes, nullptr, 2);
    ASSERT_GT(bvh.nodes.size(), 100u);
    expect_tight(bvh, boxes, "built");
    const std::vector<Aabb> moved = random_boxes();
    refit_bvh(bvh, moved);
    expect_tight(bvh, moved, "refitted");
}

TEST(Bvh, LeafLimitOutsideWhatTheWalkHoldsIsRefused) {
    const std::vector<Aabb> boxes{{dvec3(0), dvec3(1)}};
    EXPECT_EQ(build_bvh(boxes, nullptr, kMaxLeafSize).nodes.size(), 1u);
    for (const int max_leaf : {0, kMaxLeafSize + 1}) {
        try {
            build_bvh(boxes, nullptr, max_leaf);
            ADD_FAILURE() << max_leaf;
        } catch (const std::invalid_argument& e) {
            EXPECT_EQ(std::string(e.what()), "build_bvh: max_leaf " + std::to_string(max_leaf) + " is not in 1..15");
        }
    }
}

}  // namespace
}  // namespace fh
