// glTF animation samplers by hand, from the specification's Appendix C:
// STEP, LINEAR and slerp (across the 180-degree sign flip), CUBICSPLINE with
// its tangents scaled by the key interval -- at keys, between them, before
// the first and after the last.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "anim/sampler.h"

namespace fh {
namespace {

Sampler vec3(Interpolation3 i, std::vector<double> times, std::vector<double> values) {
    Sampler s;
    s.interpolation = i;
    s.times = std::move(times);
    s.values = std::move(values);
    s.components = 3;
    return s;
}

void expect_values_near(const std::vector<double>& got, const std::vector<double>& want, double tol = 1e-12) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << "component " << i;
}

TEST(AnimationSampler, StepHoldsEachKeyUntilTheNext) {
    const Sampler s = vec3(Interpolation3::step, {1, 2, 4}, {0, 0, 0, 10, 20, 30, 5, 5, 5});
    expect_values_near(sample(s, 0), {0, 0, 0});      // before the first key: its value
    expect_values_near(sample(s, 1), {0, 0, 0});      // at a key
    expect_values_near(sample(s, 1.999), {0, 0, 0});  // just before the next
    expect_values_near(sample(s, 2), {10, 20, 30});
    expect_values_near(sample(s, 3.9), {10, 20, 30});
    expect_values_near(sample(s, 4), {5, 5, 5});
    expect_values_near(sample(s, 100), {5, 5, 5});    // after the last: its value
    EXPECT_EQ(sampler_problem(s), "");
}

TEST(AnimationSampler, LinearMixesTheTwoKeysAround) {
    const Sampler s = vec3(Interpolation3::linear, {0, 2, 3}, {0, 0, 0, 4, -2, 8, 4, 6, 8});
    expect_values_near(sample(s, 0.5), {1, -0.5, 2});  // s = 0.25 of the way to key 1
    expect_values_near(sample(s, 2), {4, -2, 8});
    expect_values_near(sample(s, 2.75), {4, 4, 8});    // 0.75 of the way from (4,-2,8) to (4,6,8)
    expect_values_near(sample(s, -1), {0, 0, 0});
    expect_values_near(sample(s, 9), {4, 6, 8});
}

Sampler rotation(Interpolation3 i, std::vector<double> times, std::vector<double> quats) {
    Sampler s;
    s.interpolation = i;
    s.times = std::move(times);
    s.values = std::move(quats);
    s.components = 4;
    s.rotation = true;
    return s;
}

// A rotation of `degrees` about z as glTF writes it: x, y, z, w.
std::vector<double> about_z(double degrees) {
    const double h = degrees * std::numbers::pi / 360;
    return {0, 0, std::sin(h), std::cos(h)};
}

TEST(AnimationSampler, LinearRotationIsSlerpAlongTheShorterArc) {
    // 0 to 90 degrees about z: halfway is 45 degrees (slerp; a straight mix
    // would be 45 too here, but not unit before normalising).
    std::vector<double> keys = about_z(0);
    for (const double c : about_z(90)) keys.push_back(c);
    const Sampler quarter = rotation(Interpolation3::linear, {0, 1}, keys);
    expect_values_near(sample(quarter, 0.5), about_z(45));
    expect_values_near(sample(quarter, 0.25), about_z(22.5));
    // 170 to -170 degrees: the shorter arc passes through 180 (20 degrees),
    // not through 0 (340). -170 degrees written with w < 0 -- the same
    // rotation as +190 -- is the sign flip slerp must undo.
    std::vector<double> across = about_z(170);
    for (const double c : about_z(190)) across.push_back(c);  // = -(rotation by -170)
    const Sampler flip = rotation(Interpolation3::linear, {0, 1}, across);
    expect_values_near(sample(flip, 0.5), about_z(180), 1e-12);
    std::vector<double> negated = about_z(170);
    for (const double c : about_z(-170)) negated.push_back(c);  // the same two rotations, dot < 0
    const Sampler flipped = rotation(Interpolation3::linear, {0, 1}, negated);
    const std::vector<double> mid = sample(flipped, 0.5);
    // 180 degrees about z, up to the sign of the quaternion: |z| = 1.
    EXPECT_NEAR(std::abs(mid[2]), 1, 1e-12);
    EXPECT_NEAR(mid[3], 0, 1e-12);
    // A quarter of the way: 175 degrees (or its negative quaternion).
    const std::vector<double> q = sample(flipped, 0.25), want = about_z(175);
    const double sign = q[3] * want[3] + q[2] * want[2] < 0 ? -1 : 1;
    expect_values_near({sign * q[0], sign * q[1], sign * q[2], sign * q[3]}, want, 1e-12);
}

TEST(AnimationSampler, CubicSplineIsHermiteWithTangentsTimesTheInterval) {
    // One component varying: keys at t = 1 and t = 3 (interval 2); values
    // 0 and 10; out-tangent of key 0: 4 per second, in-tangent of key 1: -2.
    // p(s) = h00 v0 + h10 td b0 + h01 v1 + h11 td a1 with td = 2.
    Sampler s = vec3(Interpolation3::cubic_spline, {1, 3},
                     {/*key 0: in, value, out*/ 9, 9, 9, 0, 0, 0, 4, 0, 0,
                      /*key 1*/ -2, 0, 0, 10, 1, 2, 7, 7, 7});
    auto p = [](double s_, double v0, double b0, double v1, double a1, double td) {
        const double s2 = s_ * s_, s3 = s2 * s_;
        return (2 * s3 - 3 * s2 + 1) * v0 + (s3 - 2 * s2 + s_) * td * b0 + (-2 * s3 + 3 * s2) * v1 + (s3 - s2) * td * a1;
    };
    // At t = 2, s = 0.5: x = 0.5 * 0 + 0.125 * 2 * 4 + 0.5 * 10 + (-0.125) * 2 * (-2) = 1 + 5 + 0.5 = 6.5.
    EXPECT_NEAR(p(0.5, 0, 4, 10, -2, 2), 6.5, 1e-12);
    expect_values_near(sample(s, 2), {6.5, p(0.5, 0, 0, 1, 0, 2), p(0.5, 0, 0, 2, 0, 2)});
    expect_values_near(sample(s, 1.5), {p(0.25, 0, 4, 10, -2, 2), p(0.25, 0, 0, 1, 0, 2), p(0.25, 0, 0, 2, 0, 2)});
    // At the keys their values; before and after, held -- never a tangent.
    expect_values_near(sample(s, 1), {0, 0, 0});
    expect_values_near(sample(s, 3), {10, 1, 2});
    expect_values_near(sample(s, 0), {0, 0, 0});
    expect_values_near(sample(s, 5), {10, 1, 2});
    // The same curve on keys 4 seconds apart: tangents count twice as much.
    Sampler slow = s;
    slow.times = {1, 5};
    expect_values_near(sample(slow, 3), {p(0.5, 0, 4, 10, -2, 4), p(0.5, 0, 0, 1, 0, 4), p(0.5, 0, 0, 2, 0, 4)});
}

TEST(AnimationSampler, CubicSplineRotationsComeOutUnit) {
    std::vector<double> v;
    for (const double c : {0.0, 0.0, 0.0, 0.0}) v.push_back(c);  // in-tangent
    for (const double c : about_z(0)) v.push_back(c);
    for (const double c : {0.0, 0.0, 0.3, 0.0}) v.push_back(c);  // out-tangent
    for (const double c : {0.0, 0.0, 0.0, 0.0}) v.push_back(c);
    for (const double c : about_z(90)) v.push_back(c);
    for (const double c : {0.0, 0.0, 0.0, 0.0}) v.push_back(c);
    const Sampler s = rotation(Interpolation3::cubic_spline, {0, 1}, v);
    const std::vector<double> q = sample(s, 0.4);
    EXPECT_NEAR(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3], 1, 1e-12);
}

TEST(AnimationSampler, ProblemsAreNamed) {
    EXPECT_EQ(sampler_problem(vec3(Interpolation3::linear, {}, {})), "it has no keys");
    EXPECT_EQ(sampler_problem(vec3(Interpolation3::linear, {0, 0}, {1, 2, 3, 4, 5, 6})),
              "its key times do not increase (key 1)");
    EXPECT_EQ(sampler_problem(vec3(Interpolation3::linear, {0, 1}, {1, 2, 3})), "it has 3 values for 2 keys of 3");
    EXPECT_EQ(sampler_problem(vec3(Interpolation3::cubic_spline, {0}, {1, 2, 3})),
              "it has 3 values for 1 keys of 3 (times 3, CUBICSPLINE)");
    EXPECT_EQ(sampler_problem(vec3(Interpolation3::step, {0, NAN}, {1, 2, 3, 4, 5, 6})), "key 1's time is not finite");
    EXPECT_EQ(sampler_problem(vec3(Interpolation3::step, {0}, {1, INFINITY, 3})), "a value is not finite");
}

}  // namespace
}  // namespace fh
