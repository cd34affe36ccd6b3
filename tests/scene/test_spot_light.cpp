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
    const auto r = report_spot().radiance_at({0, 0, -1});
    EXPECT_NEAR(r.intensity, 2.2 / 121, 1e-15);
    EXPECT_NEAR(r.distance, 11, 1e-12);
    EXPECT_NEAR(r.to_light.z, 1, 1e-15);
}

TEST(SpotLight, FortyFiveDegreesOffAxis) {
    // (11,0,-1): theta = pi/4, d^2 = 242 -> 2.2 (1 - 1/8) / 242 = 0.0079545...
    EXPECT_NEAR(report_spot().radiance_at({11, 0, -1}).intensity, 0.007954545454545455, 1e-12);
}

TEST(SpotLight, NarrowConeFallsToZeroAtItsEdge) {
    const double a = kPi / 4;
    const auto spot = report_spot(a);
    // theta = pi/8: half way to the edge -> 2.2 * 0.5 / d^2, d = 11 / cos(pi/8).
    EXPECT_NEAR(spot.radiance_at({11 * std::tan(kPi / 8), 0, -1}).intensity, 0.00775957627812067,
                1e-12);
    // Just inside the edge: tiny; beyond it: nothing.
    const double inside = spot.radiance_at({11 * std::tan(a - 1e-6), 0, -1}).intensity;
    EXPECT_GT(inside, 0);
    EXPECT_LT(inside, 1e-7);
    EXPECT_EQ(spot.radiance_at({11 * std::tan(a + 1e-6), 0, -1}).intensity, 0);
    // Behind the light.
    EXPECT_EQ(spot.radiance_at({0, 0, 20}).intensity, 0);
}

TEST(SpotLight, AtTheLightsOwnPositionGivesNothing) {
    const auto r = report_spot().radiance_at({0, 0, 10});
    EXPECT_EQ(r.intensity, 0);
    EXPECT_TRUE(is_finite(r.to_light));
}

}  // namespace
}  // namespace fh
