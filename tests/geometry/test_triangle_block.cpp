// TriangleBlock and TriangleRows: a leaf's triangles in columns, rows a
// vector long or packed. Both of their tests -- a packet against one
// column, one ray against all columns -- must give each ray and triangle
// exactly the bits Triangle::intersect gives, or the BVH walk's answer would
// depend on how many rays of a packet reach a leaf.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "geometry/triangle_block.h"

namespace fh {
namespace {

template <typename T>
bool same_bits(T a, T b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// count triangles around the origin sharing vertices (so rays meet edges
// and corners), one of them without area when `degenerate`.
template <typename T>
std::vector<Triangle<T>> fan(std::mt19937& rng, int count, bool degenerate) {
    std::uniform_real_distribution<double> coord(-1, 1);
    auto point = [&] { return Vec3<T>(T(coord(rng)), T(coord(rng)), T(coord(rng))); };
    std::vector<Triangle<T>> out;
    Vec3<T> a = point(), b = point();
    for (int j = 0; j < count; ++j) {
        const Vec3<T> c = point();
        out.push_back(Triangle<T>::make(a, b, c, 0));
        b = c;
    }
    if (degenerate) out[0] = Triangle<T>::make(a, a, b, 0);  // a repeated vertex
    return out;
}

// Rays from a shell around the fan toward its vertices, edges' midpoints or
// random points near it.
template <typename T>
RayPacket<T> rays_at(std::mt19937& rng, const std::vector<Triangle<T>>& tris) {
    std::uniform_real_distribution<double> coord(-1, 1);
    std::uniform_int_distribution<int> pick(0, int(tris.size()) - 1), kind(0, 2);
    RayPacket<T> p;
    for (int l = 0; l < kLanes<T>; ++l) {
        const dvec3 o = 4.0 * glm::normalize(dvec3(coord(rng), coord(rng), coord(rng)));
        const Triangle<T>& t = tris[size_t(pick(rng))];
        dvec3 target(coord(rng), coord(rng), coord(rng));
        if (kind(rng) == 0) target = dvec3(t.v0);
        if (kind(rng) == 1) target = 0.5 * (dvec3(t.v1) + dvec3(t.v2));
        const Vec3<T> d = Vec3<T>(glm::normalize(target - o));
        p.origin.x[l] = T(o.x), p.origin.y[l] = T(o.y), p.origin.z[l] = T(o.z);
        p.direction.x[l] = d.x, p.direction.y[l] = d.y, p.direction.z[l] = d.z;
    }
    return p;
}

// packed: the rows as TriangleRows packs them (a row as long as the leaf,
// followed by zeros that a vector past the last row reads); else a block.
template <typename T>
void expect_columns_equal_triangles(bool packed) {
    std::mt19937 rng(11);
    int hits = 0, tests = 0;
    for (int round = 0; round < 4000; ++round) {
        const int count = 1 + round % TriangleBlock<T>::kColumns;
        const std::vector<Triangle<T>> tris = fan<T>(rng, count, round % 5 == 0);
        const TriangleBlock<T> block = TriangleBlock<T>::make(tris.data(), count);
        std::vector<T> storage(size_t(9 * count + kLanes<T>), T(0));
        TriangleRows<T>::write(tris.data(), count, count, storage.data());
        const TriangleRows<T> rows{storage.data(), count};
        auto intersect = [&](auto... args) { return packed ? rows.intersect(args...) : block.intersect(args...); };
        const RayPacket<T> ray = rays_at(rng, tris);
        const RayBasis<T> basis(ray);
        Lanes<T> t_max;
        for (int l = 0; l < kLanes<T>; ++l) t_max[l] = l % 4 == 3 ? T(3.5) : kInfinity<T>;  // some cut short
        for (int j = 0; j < count; ++j) {
            const Lanes<T> want = tris[size_t(j)].intersect(basis, T(0), t_max);
            const Lanes<T> packet = intersect(basis, j, T(0), t_max);
            for (int l = 0; l < kLanes<T>; ++l) {
                ASSERT_TRUE(same_bits(packet[l], want[l])) << "column " << j << " lane " << l;
                hits += want[l] < kInfinity<T>;
                ++tests;
            }
        }
        for (int l = 0; l < kLanes<T>; ++l)
            for (int j0 = 0; j0 < count; j0 += kLanes<T>) {
                const Lanes<T> one = intersect(basis, l, j0, count, T(0), splat(t_max[l]));
                for (int c = 0; c < kLanes<T>; ++c) {
                    const int j = j0 + c;
                    if (j >= count) {  // past the leaf's triangles: nothing
                        ASSERT_EQ(one[c], kInfinity<T>);
                        continue;
                    }
                    const T want = tris[size_t(j)].intersect(basis, T(0), t_max)[l];
                    ASSERT_TRUE(same_bits(one[c], want)) << "ray " << l << " column " << j;
                }
            }
    }
    EXPECT_GT(hits, tests / 20);  // the rays do meet the triangles (about 1 test in 8)
}

TEST(TriangleBlock, FloatTestsGiveEachTrianglesOwnBits) { expect_columns_equal_triangles<float>(false); }
TEST(TriangleBlock, DoubleTestsGiveEachTrianglesOwnBits) { expect_columns_equal_triangles<double>(false); }
TEST(TriangleRows, FloatPackedTestsGiveEachTrianglesOwnBits) { expect_columns_equal_triangles<float>(true); }
TEST(TriangleRows, DoublePackedTestsGiveEachTrianglesOwnBits) { expect_columns_equal_triangles<double>(true); }

TEST(TriangleBlock, ATriangleWithoutAreaAndUnusedColumnsNeverHit) {
    const Triangle<double> flat = Triangle<double>::make({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, 0);
    const Triangle<double> real = Triangle<double>::make({-1, -1, 1}, {1, -1, 1}, {0, 1, 1}, 0);
    ASSERT_TRUE(flat.degenerate());
    const Triangle<double> tris[2] = {flat, real};
    const TriangleBlock<double> block = TriangleBlock<double>::make(tris, 2);
    // Straight down the z axis: through the real triangle at t = 1 and the
    // flat one's line at t = 2.
    const RayPacket<double> ray = RayPacket<double>::splat({{0, 0, 2}, {0, 0, -1}});
    const RayBasis<double> basis(ray);
    const Lanes<double> t = block.intersect(basis, 0, 0, 2, 0.0, splat(kInfinity<double>));
    EXPECT_EQ(t[0], kInfinity<double>);
    EXPECT_EQ(t[1], 1.0);
    for (int c = 2; c < kLanes<double>; ++c) EXPECT_EQ(t[c], kInfinity<double>);
    EXPECT_EQ(block.intersect(basis, 0, 0.0, splat(kInfinity<double>))[0], kInfinity<double>);
}

TEST(Lanes, SplatLaneBitsAndForEachLane) {
    Lanes<float> v;
    for (int l = 0; l < kLanes<float>; ++l) v[l] = float(10 * l);
    const Lanes<float> s = splat_lane(v, kLanes<float> - 1);
    for (int l = 0; l < kLanes<float>; ++l) EXPECT_EQ(s[l], float(10 * (kLanes<float> - 1)));
    const LaneInts<float> odd = (lane_index<float>() & 1) != 0;
    EXPECT_EQ(lane_bits(odd), 0xAAAAAAAAu & ((1u << kLanes<float>) - 1));
    EXPECT_EQ(count(odd), kLanes<float> / 2);
    std::vector<int> seen;
    EXPECT_TRUE(for_each_lane(odd, [&](int i) {
        seen.push_back(i);
        return i == 3;  // stops here
    }));
    EXPECT_EQ(seen, (std::vector<int>{1, 3}));
}

}  // namespace
}  // namespace fh
