// Each intersection with hand-worked hits, misses, t values and normals,
// in both scalar types.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geometry/plane.h"
#include "geometry/sphere.h"
#include "geometry/triangle.h"
#include "render/flat_scene.h"  // Shape::surface: the hit point as shading finds it

namespace fh {
namespace {

template <typename T>
class Intersections : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Intersections, Scalars);

template <typename T>
Ray<T> ray(Vec3<T> o, Vec3<T> d) {
    return {o, glm::normalize(d)};
}

template <typename T>
std::vector<T> lanes_of(const Lanes<T>& v) {
    std::vector<T> out(kLanes<T>);
    store(out.data(), v);
    return out;
}

TYPED_TEST(Intersections, SphereFrontHitAndNormal) {
    using T = TypeParam;
    const Sphere<T> red{{-3, 0, 0}, 1, 0};  // report Table 2
    const auto r = ray<T>({-3, 0, 10}, {0, 0, -1});
    const T t = red.intersect(r, 0, kInfinity<T>);
    EXPECT_NEAR(t, 9, 1e-5);  // top of the sphere at z = 1
    Vec3<T> p, n;
    red.surface().project(r.at(t), p, n);
    EXPECT_NEAR(p.z, 1, 1e-6);
    EXPECT_NEAR(n.x, 0, 1e-6);
    EXPECT_NEAR(n.z, 1, 1e-6);
}

TYPED_TEST(Intersections, SphereObliqueHit) {
    using T = TypeParam;
    // From (0,0,5) toward the origin along (1,0,-1)/sqrt2 offset: aim at the
    // unit sphere's point (sqrt(1/2), 0, sqrt(1/2)) from straight above it.
    const Sphere<T> s{{0, 0, 0}, 1, 0};
    const T h = T(std::sqrt(0.5));
    const auto r = ray<T>({h, 0, 5}, {0, 0, -1});
    EXPECT_NEAR(s.intersect(r, 0, kInfinity<T>), 5 - h, 1e-5);
    Vec3<T> p, n;
    s.surface().project(r.at(5 - h), p, n);
    EXPECT_NEAR(n.x, h, 1e-5);
    EXPECT_NEAR(n.z, h, 1e-5);
}

TYPED_TEST(Intersections, SphereMissesAndRaysPointingAway) {
    using T = TypeParam;
    const Sphere<T> s{{0, 0, 0}, 1, 0};
    EXPECT_EQ(s.intersect(ray<T>({0, 1.001f, -5}, {0, 0, 1}), 0, kInfinity<T>), kInfinity<T>);
    EXPECT_EQ(s.intersect(ray<T>({0, 0, 5}, {0, 0, 1}), 0, kInfinity<T>), kInfinity<T>);  // behind
    // t_max cuts the hit off.
    EXPECT_EQ(s.intersect(ray<T>({0, 0, -5}, {0, 0, 1}), 0, 3), kInfinity<T>);
}

TYPED_TEST(Intersections, SphereFromInsideTakesTheFarRoot) {
    using T = TypeParam;
    const Sphere<T> s{{0, 0, 0}, 2, 0};
    EXPECT_NEAR(s.intersect(ray<T>({0, 0, 0}, {1, 0, 0}), 0, kInfinity<T>), 2, 1e-6);
}

TYPED_TEST(Intersections, SpherePacketOfRaysLeavingItKeepsTheOneThatHits) {
    // Rays leaving the sphere (both roots behind them) let a packet skip the
    // root's square root -- but not a packet where one ray still hits.
    using T = TypeParam;
    const Sphere<T> s{{0, 0, 0}, 1, 0};
    const T h = T(std::sqrt(0.5));
    RayPacket<T> p = RayPacket<T>::splat(ray<T>({0, 0, 1}, {0, 0, 1}));  // leaving the top
    for (int i = 0; i < kLanes<T>; ++i) {
        const Ray<T> r = i % 3 == 0 ? ray<T>({h, 0, h}, {1, 0, 1})    // leaving, on the surface
                         : i % 3 == 1 ? ray<T>({0, 0, 3}, {0, 1, 2})  // outside, sphere behind
                                      : ray<T>({0, -1, 0}, {0, -1, 0});
        p.origin.x[i] = r.origin.x, p.origin.y[i] = r.origin.y, p.origin.z[i] = r.origin.z;
        p.direction.x[i] = r.direction.x, p.direction.y[i] = r.direction.y, p.direction.z[i] = r.direction.z;
    }
    for (const T t : lanes_of<T>(s.intersect(p, 0, splat(kInfinity<T>)))) EXPECT_EQ(t, kInfinity<T>);
    // The last lane now comes from below, toward the bottom at z = -1.
    const int last = kLanes<T> - 1;
    p.origin.x[last] = 0, p.origin.y[last] = 0, p.origin.z[last] = -4;
    p.direction.x[last] = 0, p.direction.y[last] = 0, p.direction.z[last] = 1;
    const auto t = lanes_of<T>(s.intersect(p, 0, splat(kInfinity<T>)));
    for (int i = 0; i < last; ++i) EXPECT_EQ(t[size_t(i)], kInfinity<T>) << i;
    EXPECT_NEAR(t[size_t(last)], 3, 1e-6);
    // Or from inside, past the centre: its closest approach is behind it too
    // (b < 0), but it starts inside (c < 0) and meets the far side at t = 0.5.
    p.origin.z[last] = T(0.5);
    const auto inside = lanes_of<T>(s.intersect(p, 0, splat(kInfinity<T>)));
    for (int i = 0; i < last; ++i) EXPECT_EQ(inside[size_t(i)], kInfinity<T>) << i;
    EXPECT_NEAR(inside[size_t(last)], 0.5, 1e-6);
}

TYPED_TEST(Intersections, PlaneHitsFromAboveAndBelow) {
    using T = TypeParam;
    const Plane<T> floor{{0, 0, 1}, -1, 0};  // report Table 3: z = -1
    EXPECT_NEAR(floor.intersect(ray<T>({0, 0, 10}, {0, 0, -1}), 0, kInfinity<T>), 11, 1e-5);
    EXPECT_NEAR(floor.intersect(ray<T>({0, 0, -5}, {0, 0, 1}), 0, kInfinity<T>), 4, 1e-5);
    // (0,0,1) along (1,0,-1)/sqrt2: t = (-1 - 1) / (-1/sqrt2) = 2 sqrt2.
    EXPECT_NEAR(floor.intersect(ray<T>({0, 0, 1}, {1, 0, -1}), 0, kInfinity<T>), 2 * std::sqrt(2.0),
                1e-5);
    Vec3<T> p, n;
    floor.surface().project(ray<T>({3, 4, 10}, {0, 0, -1}).at(11), p, n);
    EXPECT_EQ(p.z, T(-1));
    EXPECT_EQ(n, Vec3<T>(0, 0, 1));
}

TYPED_TEST(Intersections, PlaneMissesParallelAndReceding) {
    using T = TypeParam;
    const Plane<T> floor{{0, 0, 1}, -1, 0};
    EXPECT_EQ(floor.intersect(ray<T>({0, 0, 10}, {1, 0, 0}), 0, kInfinity<T>), kInfinity<T>);
    EXPECT_EQ(floor.intersect(ray<T>({0, 0, 10}, {0, 0, 1}), 0, kInfinity<T>), kInfinity<T>);
}

TYPED_TEST(Intersections, TriangleNormalAndHit) {
    using T = TypeParam;
    // The tetrahedron's base (report Table 4, row 1): (v1-v0) x (v2-v0) = (0,0,-4).
    const auto tri = Triangle<T>::make({-5, 5, 0}, {-7, 5, 0}, {-6, 7, 0}, 0);
    EXPECT_EQ(tri.normal, Vec3<T>(0, 0, -1));
    EXPECT_NEAR(tri.intersect(ray<T>({-6, 6, 10}, {0, 0, -1}), 0, kInfinity<T>), 10, 1e-5);
    // Outside the triangle, beside each edge.
    EXPECT_EQ(tri.intersect(ray<T>({-6, 4.9f, 10}, {0, 0, -1}), 0, kInfinity<T>), kInfinity<T>);
    EXPECT_EQ(tri.intersect(ray<T>({-5, 7, 10}, {0, 0, -1}), 0, kInfinity<T>), kInfinity<T>);
    EXPECT_EQ(tri.intersect(ray<T>({-7, 7, 10}, {0, 0, -1}), 0, kInfinity<T>), kInfinity<T>);
    // In the triangle's plane: no single crossing point.
    EXPECT_EQ(tri.intersect(ray<T>({-9, 6, 0}, {1, 0, 0}), 0, kInfinity<T>), kInfinity<T>);
}

TYPED_TEST(Intersections, TriangleSlantedFace) {
    using T = TypeParam;
    // Face 2 of the tetrahedron: (-5,5,0) (-7,5,0) (-6,6,5).
    // (v1-v0) x (v2-v0) = (-2,0,0) x (-1,1,5) = (0, 10, -2) -> normalize.
    const auto tri = Triangle<T>::make({-5, 5, 0}, {-7, 5, 0}, {-6, 6, 5}, 0);
    const T len = T(std::sqrt(104.0));
    EXPECT_NEAR(tri.normal.y, 10 / len, 1e-6);
    EXPECT_NEAR(tri.normal.z, -2 / len, 1e-6);
    // A ray along +y at x = -6, z = 1 crosses the face where y = 5 + z/5 = 5.2.
    EXPECT_NEAR(tri.intersect(ray<T>({-6, 0, 1}, {0, 1, 0}), 0, kInfinity<T>), 5.2, 1e-5);
}

TYPED_TEST(Intersections, DegenerateTriangleHasNoNormal) {
    using T = TypeParam;
    const auto tri = Triangle<T>::make({0, 0, 0}, {1, 1, 1}, {2, 2, 2}, 0);
    EXPECT_EQ(tri.normal, Vec3<T>(0));
}

}  // namespace
}  // namespace fh
