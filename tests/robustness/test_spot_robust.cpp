// The spot light's intensity is finite and continuous at its
// hard points: theta exactly at max_angle, a point at the light's position,
// cosines that round to just above 1, and max_angle >= pi.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "robust_util.h"
#include "scene/spot_light.h"

namespace fh {
namespace {

using namespace fh::robust;

constexpr double kPiSpot = 3.14159265358979323846;

template <typename T>
class SpotRobust : public ::testing::Test {};
TYPED_TEST_SUITE(SpotRobust, Scalars);

template <typename T>
SpotLight<T> spot(double max_angle, dvec3 axis = {0, 0, -1}, dvec3 position = {0, 0, 10}) {
    SpotLight<T> s;
    s.color = Color<T>(255);
    s.intensity = T(2.2);
    s.position = Vec3<T>(position);
    s.axis = Vec3<T>(glm::normalize(axis));
    s.max_angle = T(max_angle);
    return s;
}

// The point at angle theta off the axis, at distance d from the light, in the
// plane of the axis and x.
template <typename T>
Vec3<T> at_angle(const SpotLight<T>& s, double theta, double d) {
    const dvec3 a(s.axis);
    const dvec3 side = glm::normalize(glm::cross(a, glm::cross(dvec3(1, 0.1, 0), a)));
    return Vec3<T>(dvec3(s.position) + d * (std::cos(theta) * a + std::sin(theta) * side));
}

// Expected intensity from docs/model.md section 4.
double expected(double I, double theta, double max_angle, double d) {
    return theta <= max_angle ? I * std::max(0.0, 1 - theta / max_angle) / (d * d) : 0;
}

TYPED_TEST(SpotRobust, ExactlyAtTheConeEdgeIsZeroAndContinuous) {
    using T = TypeParam;
    const double tol = std::is_same_v<T, float> ? 2e-3 : 1e-7;  // in angle, radians
    for (const double max_angle : {kPiSpot / 4, kPiSpot / 2, 2.0, kPiSpot}) {
        const auto s = spot<T>(max_angle);
        // Walk across the edge in steps of 1e-4 rad: the intensity falls
        // linearly to 0 and stays 0, with no jump anywhere.
        double previous = -1;
        for (int k = -20; k <= 20; ++k) {
            const double theta = std::min(kPiSpot, max_angle + k * 1e-4);
            const auto r = s.radiance_at(at_angle(s, theta, 5));
            ASSERT_TRUE(std::isfinite(r.intensity));
            ASSERT_TRUE(is_finite(r.to_light));
            const double want = expected(2.2, theta, max_angle, 5);
            // Within the slope times the angle the tracer can resolve.
            EXPECT_NEAR(double(r.intensity), want, 2.2 / 25 * tol / max_angle + 1e-6 * want)
                << "max_angle " << max_angle << " theta " << theta;
            if (previous >= 0)
                EXPECT_LE(std::abs(double(r.intensity) - previous), 2.2 / 25 * (1e-4 + 2 * tol) / max_angle);
            previous = double(r.intensity);
        }
        // Exactly at the edge: nothing (continuous with the outside).
        EXPECT_NEAR(double(s.radiance_at(at_angle(s, max_angle, 5)).intensity), 0,
                    2.2 / 25 * tol / max_angle);
    }
}

TYPED_TEST(SpotRobust, AtAndNearTheLightsPosition) {
    using T = TypeParam;
    const auto s = spot<T>(2 * kPiSpot, {1, -2, 0.5}, {1.25, -3.5, 7});
    const auto at = s.radiance_at(s.position);
    EXPECT_EQ(at.intensity, T(0));
    EXPECT_TRUE(is_finite(at.to_light));
    EXPECT_EQ(at.distance, T(0));
    // Arbitrarily close: large (the 1/d^2 law), but finite and never NaN --
    // also for a light at the origin, where d^2 can be a subnormal number
    // (1e-40 in float, 1e-320 in double) and I / d^2 would overflow.
    for (const dvec3 pos : {dvec3(s.position), dvec3(0)}) {
        auto near = spot<T>(2 * kPiSpot, {1, -2, 0.5}, pos);
        double previous = 0;
        for (const double d : {1e-3, 1e-6, 1e-9, 1e-15, 1e-20, 1e-30, 1e-160, 1e-170, 1e-300}) {
            const auto r = near.radiance_at(near.position + Vec3<T>(T(d), T(0), T(0)));
            EXPECT_FALSE(std::isnan(r.intensity)) << d;
            EXPECT_TRUE(std::isfinite(r.intensity)) << d;
            EXPECT_TRUE(is_finite(r.to_light)) << d;
            EXPECT_GE(r.intensity, T(0));
            // Closer never means darker, until the point is the light's own
            // position (to the scalar's resolution), which gets nothing.
            if (r.distance > T(0)) {
                EXPECT_GE(double(r.intensity), previous) << d;
                previous = double(r.intensity);
            }
        }
    }
}

// Points exactly on the axis, for axes whose normalisation makes the cosine
// round to just above 1 (or below -1 behind the light): acos would be NaN
// without the clamp.
TYPED_TEST(SpotRobust, CosinesRoundingPastOne) {
    using T = TypeParam;
    std::mt19937_64 rng(8);
    int above_one = 0;
    for (int i = 0; i < 20000; ++i) {
        const dvec3 axis = random_unit(rng);
        for (const double max_angle : {kPiSpot / 4, kPiSpot, 2 * kPiSpot}) {
            const auto s = spot<T>(max_angle, axis, {0.5, -0.25, 3});
            const double d = 1 + 10 * (i % 7);
            for (const double sign : {1.0, -1.0}) {  // ahead on the axis and behind the light
                const Vec3<T> p = s.position + T(sign * d) * s.axis;
                const Vec3<T> delta = s.position - p;
                const T len = std::sqrt(glm::dot(delta, delta));
                if (std::abs(-glm::dot(delta / len, s.axis)) > T(1)) ++above_one;
                const auto r = s.radiance_at(p);
                ASSERT_TRUE(std::isfinite(r.intensity));
                const double theta = sign > 0 ? 0 : kPiSpot;
                const double want = expected(2.2, theta, max_angle, d);
                const double slope = 2.2 / (d * d) / max_angle;  // per radian
                // acos near 0 and pi is sensitive: sqrt(2 eps) rad of error.
                const double angle_tol = std::sqrt(2 * double(std::numeric_limits<T>::epsilon())) * 2;
                EXPECT_NEAR(double(r.intensity), want, slope * angle_tol + 1e-5 * want);
            }
        }
    }
    // The case is real: some cosines did round past 1.
    EXPECT_GT(above_one, 0);
}

TYPED_TEST(SpotRobust, WideConesAreContinuousAllAround) {
    using T = TypeParam;
    // max_angle >= pi: every direction lit; at theta = pi (straight behind)
    // the intensity is I (1 - pi/max_angle) / d^2, and the whole sweep from 0
    // to pi is continuous.
    for (const double max_angle : {kPiSpot, kPiSpot + 1e-9, 4.0, 2 * kPiSpot, 100.0}) {
        const auto s = spot<T>(max_angle, {0.2, 0.1, -1});
        double previous = -1;
        for (int k = 0; k <= 2000; ++k) {
            const double theta = kPiSpot * k / 2000;
            const auto r = s.radiance_at(at_angle(s, theta, 3));
            ASSERT_TRUE(std::isfinite(r.intensity));
            const double want = expected(2.2, theta, max_angle, 3);
            EXPECT_NEAR(double(r.intensity), want, 2.2 / 9 * 2e-3 / max_angle + 1e-5 * want)
                << "max_angle " << max_angle << " theta " << theta;
            if (previous >= 0)
                EXPECT_LE(std::abs(double(r.intensity) - previous), 2.2 / 9 * (kPiSpot / 2000 + 2e-3) / max_angle);
            previous = double(r.intensity);
        }
    }
}

// Item 11: the report's scene lit by narrow, edge-on and all-round spots,
// some placed on a surface, renders with no non-finite sample.
TYPED_TEST(SpotRobust, RenderedSpotsAreFinite) {
    using T = TypeParam;
    for (const double max_angle : {1e-6, kPiSpot / 4, kPiSpot, 2 * kPiSpot}) {
        for (const dvec3 pos : {dvec3(0, 0, 10), dvec3(0, 0, -1), dvec3(-3, 0, 1), dvec3(-6, 6, 5)}) {
            Scene s;
            const int m = add_material(s, "m", material({130, 130, 130}, 0.1, 0.5, 10.5, 100, true, 0.05));
            s.planes.push_back({{0, 0, 1}, -1, m});
            s.spheres().push_back({{-3, 0, 0}, 1, m});  // pos (-3,0,1) is on its top
            s.triangles.push_back(Triangle<double>::make({-5, 5, 0}, {-7, 5, 0}, {-6, 6, 5}, m));
            s.spot_lights.push_back({"s", {255, 255, 255}, 2.2, pos, {0, 0, -1}, max_angle});
            const auto r = render(s, camera(Projection::perspective, {2, -10, 10}, {0, 2, -1}, {0, 0, 1}, 40),
                                  precision_of<T>(), all_effects());
            expect_finite_frame(r, "spot max_angle " + std::to_string(max_angle));
        }
    }
}

}  // namespace
}  // namespace fh
