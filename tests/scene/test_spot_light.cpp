// The spot light's falloff as docs/model.md section 4 reads it.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/spot_light.h"

namespace fh {
namespace {

constexpr double kPiCone = 3.14159265358979323846;

SpotLight<double> report_spot(double max_angle = 2 * kPiCone) {
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
    const double a = kPiCone / 4;
    const auto spot = report_spot(a);
    // theta = pi/8: half way to the edge -> 2.2 * 0.5 / d^2, d = 11 / cos(pi/8).
    EXPECT_NEAR(spot.radiance_at(dvec3{11 * std::tan(kPiCone / 8), 0, -1}).intensity, 0.00775957627812067,
                1e-12);
    // Just inside the edge: tiny; beyond it: nothing.
    const double inside = spot.radiance_at(dvec3{11 * std::tan(a - 1e-6), 0, -1}).intensity;
    EXPECT_GT(inside, 0);
    EXPECT_LT(inside, 1e-7);
    EXPECT_EQ(spot.radiance_at(dvec3{11 * std::tan(a + 1e-6), 0, -1}).intensity, 0);
    // Behind the light.
    EXPECT_EQ(spot.radiance_at(dvec3{0, 0, 20}).intensity, 0);
}

// A glTF spot: outer pi/4, inner pi/8. Inside the inner cone the light is
// full; between the cones s = (cos theta - cos pi/4) / (cos pi/8 - cos pi/4)
// and the light s^2 (KHR_lights_punctual's falloff); at the outer cone it is
// gone. The point is on the plane z = -1, 11 below the light: d = 11 /
// cos(theta).
TEST(SpotLight, AGltfSpotIsLitFullyInItsInnerConeThenFallsAsSSquared) {
    auto spot = report_spot(kPiCone / 4);
    spot.inner_angle = kPiCone / 8;
    spot.gltf_cone = true;
    auto at = [&](double theta) {
        const double d = 11 / std::cos(theta);
        return spot.radiance_at(dvec3{11 * std::tan(theta), 0, -1}).intensity * d * d / 2.2;
    };
    EXPECT_NEAR(at(0), 1, 1e-12);
    EXPECT_NEAR(at(kPiCone / 16), 1, 1e-12);  // inside the inner cone
    EXPECT_NEAR(at(kPiCone / 8 - 1e-6), 1, 1e-12);
    // s = (0.8314696 - 0.7071068) / (0.9238795 - 0.7071068) = 0.5737014.
    EXPECT_NEAR(at(3 * kPiCone / 16), 0.32913329741604624, 1e-12);
    // Where cos theta is half way between the cones' cosines: s = 1/2.
    EXPECT_NEAR(at(0.6172155603878475), 0.25, 1e-12);
    EXPECT_LT(at(kPiCone / 4 - 1e-6), 1e-10);
    EXPECT_EQ(at(kPiCone / 4 + 1e-6), 0);
    // With no inner cone (inner 0): s = (cos pi/8 - cos pi/4) / (1 - cos pi/4).
    spot.inner_angle = 0;
    EXPECT_NEAR(at(kPiCone / 8), 0.5477605437034694, 1e-12);
    // The report's spot ignores an inner angle: 1 - theta / (pi/4).
    spot.gltf_cone = false;
    spot.inner_angle = kPiCone / 8;
    EXPECT_NEAR(at(kPiCone / 16), 0.75, 1e-9);
    EXPECT_NEAR(at(3 * kPiCone / 16), 0.25, 1e-9);
}

TEST(SpotLight, AtTheLightsOwnPositionGivesNothing) {
    const auto r = report_spot().radiance_at(dvec3{0, 0, 10});
    EXPECT_EQ(r.intensity, 0);
    EXPECT_TRUE(is_finite(r.to_light));
}

}  // namespace
}  // namespace fh
