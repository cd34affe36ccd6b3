// The spot light's falloff as docs/model.md section 4 reads it.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/spot_light.h"

namespace fh {
namespace {

constexpr double kPi = 3.14159265358979323846;

SpotLight<double> report_spot(double max_angle = 2 * kPi) {
    SpotLight<double> s;
    s.color = {255, 255, 255};
    s.intensity = 2.2;
    s.position = {0, 0, 10};
    s.axis = {0, 0, -1};
    s.max_angle = max_angle;
    return s;
}

TEST(SpotLight, OnTheAxisFallsWithDistanceSquared) {
    // (0,0,-1): d = 11, theta = 0 -> 2.2 / 121.
    const auto r = report_spot().radiance_at(dvec3{0, 0, -1});
    EXPECT_NEAR(r.intensity, 2.2 / 121, 1e-15);
    EXPECT_NEAR(r.distance, 11, 1e-12);
    EXPECT_NEAR(r.to_light.z, 1, 1e-15);
}

TEST(SpotLight, FortyFiveDegreesOffAxis) {
    // (11,0,-1): theta = pi/4, d^2 = 242 -> 2.2 (1 - 1/8) / 242 = 0.0079545...
    EXPECT_NEAR(report_spot().radiance_at(dvec3{11, 0, -1}).intensity, 0.007954545454545455, 1e-12);
}

TEST(SpotLight, NarrowConeFallsToZeroAtItsEdge) {
    const double a = kPi / 4;
    const auto spot = report_spot(a);
    // theta = pi/8: half way to the edge -> 2.2 * 0.5 / d^2, d = 11 / cos(pi/8).
    EXPECT_NEAR(spot.radiance_at(dvec3{11 * std::tan(kPi / 8), 0, -1}).intensity, 0.00775957627812067,
                1e-12);
    // Just inside the edge: tiny; beyond it: nothing.
    const double inside = spot.radiance_at(dvec3{11 * std::tan(a - 1e-6), 0, -1}).intensity;
    EXPECT_GT(inside, 0);
    EXPECT_LT(inside, 1e-7);
    EXPECT_EQ(spot.radiance_at(dvec3{11 * std::tan(a + 1e-6), 0, -1}).intensity, 0);
    // Behind the light.
    EXPECT_EQ(spot.radiance_at(dvec3{0, 0, 20}).intensity, 0);
}

// A glTF spot's inner cone: outer pi/4, inner pi/8. Inside the inner cone
// the light is full; between the cones it falls linearly in theta,
// (pi/4 - theta) / (pi/4 - pi/8); at the outer cone it is gone. The point is
// on the plane z = -1, 11 below the light: d = 11 / cos(theta).
TEST(SpotLight, AnInnerConeIsLitFullyThenFallsLinearlyToTheOuterCone) {
    auto spot = report_spot(kPi / 4);
    spot.inner_angle = kPi / 8;
    auto at = [&](double theta) {
        const double d = 11 / std::cos(theta);
        return spot.radiance_at(dvec3{11 * std::tan(theta), 0, -1}).intensity * d * d / 2.2;
    };
    EXPECT_NEAR(at(0), 1, 1e-12);
    EXPECT_NEAR(at(kPi / 16), 1, 1e-12);              // inside the inner cone
    EXPECT_NEAR(at(kPi / 8 - 1e-6), 1, 1e-12);
    EXPECT_NEAR(at(3 * kPi / 16), 0.5, 1e-9);         // half way between the cones
    EXPECT_NEAR(at(7 * kPi / 32), 0.25, 1e-9);        // three quarters of the way
    EXPECT_LT(at(kPi / 4 - 1e-6), 1e-5);
    EXPECT_EQ(at(kPi / 4 + 1e-6), 0);
    // Without it (inner 0) the report's factor: 1 - theta / (pi/4).
    spot.inner_angle = 0;
    EXPECT_NEAR(at(kPi / 16), 0.75, 1e-9);
    EXPECT_NEAR(at(3 * kPi / 16), 0.25, 1e-9);
}

TEST(SpotLight, AtTheLightsOwnPositionGivesNothing) {
    const auto r = report_spot().radiance_at(dvec3{0, 0, 10});
    EXPECT_EQ(r.intensity, 0);
    EXPECT_TRUE(is_finite(r.to_light));
}

}  // namespace
}  // namespace fh
