// Rays parallel to a plane, lying in it, and nearly parallel
// (n.d ~ 1e-8): no hit, no NaN, no infinite t. Also for the triangle, whose
// plane the same rays can lie in.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geometry/plane.h"
#include "geometry/triangle.h"
#include "robust_util.h"
#include "render/flat_scene.h"  // Shape::surface: the hit point as shading finds it

namespace fh {
namespace {

using namespace fh::robust;

template <typename T>
class PlaneRobust : public ::testing::Test {};
TYPED_TEST_SUITE(PlaneRobust, Scalars);

// A direction with n.d = cos exactly as far as T can say: tilt a unit vector in
// the plane by `cos` toward n.
template <typename T>
Vec3<T> tilted(const dvec3& in_plane, const dvec3& n, double cos) {
    return Vec3<T>(glm::normalize(std::sqrt(1 - cos * cos) * in_plane + cos * n));
}

TYPED_TEST(PlaneRobust, ParallelInPlaneAndNearlyParallel) {
    using T = TypeParam;
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int i = 0; i < 5000; ++i) {
        const dvec3 n = random_unit(rng);
        const double dist = (u01(rng) - 0.5) * 2e3;
        const Plane<T> plane{Vec3<T>(n), T(dist), 0};
        const dvec3 in_plane = random_perpendicular(rng, dvec3(plane.normal));
        const dvec3 on = dist * dvec3(plane.normal) + 50.0 * random_perpendicular(rng, dvec3(plane.normal));
        // Parallel, above and below the plane: exactly n.d = 0 in T, so take
        // the direction perpendicular to T's own normal.
        const Vec3<T> par = Vec3<T>(glm::normalize(glm::cross(dvec3(plane.normal), random_unit(rng))));
        for (const double height : {-1.0, 1e-3, 1.0, 1e3}) {
            const Vec3<T> o(on + height * dvec3(plane.normal));
            const T t = plane.intersect({o, par}, T(0), kInfinity<T>);
            EXPECT_EQ(t, kInfinity<T>) << "parallel ray at height " << height;
        }
        // Lying in the plane.
        const T t_in = plane.intersect({Vec3<T>(on), Vec3<T>(in_plane)}, T(0), kInfinity<T>);
        EXPECT_EQ(t_in, kInfinity<T>);
        // Nearly parallel: |n.d| about 1e-8 (and 1e-9, 1e-12), both signs,
        // from above and below: never a hit, never NaN, never an infinite or
        // absurd t.
        for (const double c : {1e-8, -1e-8, 3e-9, -1e-12}) {
            const Vec3<T> d = tilted<T>(in_plane, dvec3(plane.normal), c);
            for (const double height : {-1.0, 1.0, 1e-6}) {
                const Vec3<T> o(on + height * dvec3(plane.normal));
                const T t = plane.intersect({o, d}, T(0), kInfinity<T>);
                EXPECT_FALSE(std::isnan(t));
                EXPECT_EQ(t, kInfinity<T>) << "n.d = " << c << ", height " << height;
                // point_at is only asked for hits; the result of a miss is the
                // no-hit value, never a finite absurd distance.
            }
        }
    }
}

// Just past the parallel limit a plane is hit at a large but finite t, and the
// point found lies on the plane.
TYPED_TEST(PlaneRobust, JustAboveTheParallelLimitIsFinite) {
    using T = TypeParam;
    const Plane<T> floor{{0, 0, 1}, T(-1), 0};
    const double c = 4 * double(ParallelLimit<T>::value);
    const Ray<T> r{{T(0), T(0), T(1)}, tilted<T>({1, 0, 0}, {0, 0, 1}, -c)};
    const T t = floor.intersect(r, T(0), kInfinity<T>);
    ASSERT_TRUE(std::isfinite(t));
    EXPECT_NEAR(double(t), 2 / c, 1e-4 * 2 / c);
    Vec3<T> p, n;
    floor.surface().project(r.at(t), p, n);  // as shading finds the hit point
    EXPECT_TRUE(is_finite(p));
    EXPECT_EQ(p.z, T(-1));
}

// The triangle: rays in its plane, parallel to it, and at n.d ~ 1e-8 through
// its interior never hit and never give NaN.
TYPED_TEST(PlaneRobust, TriangleParallelAndNearlyParallel) {
    using T = TypeParam;
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> u01(0, 1);
    for (int i = 0; i < 5000; ++i) {
        const dvec3 a = 10.0 * random_unit(rng), b = a + 3.0 * random_unit(rng), c = a + 3.0 * random_unit(rng);
        const auto tri = Triangle<T>::make(Vec3<T>(a), Vec3<T>(b), Vec3<T>(c), 0);
        if (tri.normal == Vec3<T>(0)) continue;
        const dvec3 n(tri.normal);
        const double wa = u01(rng), wb = u01(rng) * (1 - wa);
        const dvec3 inside = a + wb * (b - a) + (1 - wa - wb) * (c - a) * 0.999;
        const dvec3 in_plane = glm::normalize(glm::cross(n, random_unit(rng)));
        for (const double cos : {0.0, 1e-8, -1e-8, 1e-12}) {
            const Vec3<T> d = tilted<T>(in_plane, n, cos);
            // Starting on the triangle's plane, 5 units before the inside point.
            const Vec3<T> o(inside - 5.0 * dvec3(d));
            const T t = tri.intersect({o, d}, T(0), kInfinity<T>);
            EXPECT_FALSE(std::isnan(t));
            // A ray within ~1e-8 of the plane may touch an edge on the way, at
            // the distance it crosses the triangle; it never gives an
            // infinite or absurd t.
            if (t != kInfinity<T>) EXPECT_LT(double(t), 40.0) << "cos " << cos;
        }
    }
}

// Item 11: a camera lying in a plane, looking along it (every primary ray
// parallel or nearly parallel to it), renders without a non-finite sample.
TYPED_TEST(PlaneRobust, RenderedAlongThePlane) {
    using T = TypeParam;
    Scene s;
    const int m = add_material(s, "m", material({130, 130, 130}, 0.1, 0.5, 10.5, 100, true, 0.5));
    s.planes.push_back({{0, 0, 1}, -1, m});
    s.planes.push_back({glm::normalize(dvec3(1, 1e-9, 0)), 50, m});
    s.ambient_lights.push_back({"a", {255, 255, 255}, 0.01});
    s.directional_lights.push_back({"d", {255, 255, 230}, 0.02, glm::normalize(dvec3(-50, 50, -50))});
    s.spot_lights.push_back({"s", {255, 255, 255}, 2.2, {0, 0, 10}, {0, 0, -1}, 6.283185307179586});
    for (const auto proj : {Projection::perspective, Projection::orthographic}) {
        const auto r = render(s, camera(proj, {0, 0, -1}, {1, 0, 0}, {0, 0, 1}, 48), precision_of<T>(),
                              all_effects());
        expect_finite_frame(r, "camera in the plane");
    }
}

}  // namespace
}  // namespace fh
