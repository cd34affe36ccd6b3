// Camera paths: fixed values, orbits, toward, keyframes (docs/model.md section 5).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "anim/path.h"
#include "support/expect_vec.h"

namespace fh {
namespace {

using test::expect_vec_near;

dvec3 at(const Path& p, int frame, int n = 100, dvec3 eye = dvec3(0)) {
    return evaluate(p, frame, n, eye);
}

Keyframes keys(std::vector<Keyframe> k, Interpolation interp) {
    return Keyframes{std::move(k), interp};
}

TEST(Path, FixedValueIgnoresFrame) {
    const Path p = dvec3(1, 2, 3);
    EXPECT_EQ(at(p, 0), dvec3(1, 2, 3));
    EXPECT_EQ(at(p, 57), dvec3(1, 2, 3));
}

TEST(Path, OrbitQuarterTurns) {
    const Path p = Orbit{dvec3(1, 2, 3), dvec3(4, 0, 0), dvec3(0, 0, 5), 1};
    expect_vec_near(at(p, 0), dvec3(1, 2, 8));    // phi = 0: center + cos
    expect_vec_near(at(p, 25), dvec3(5, 2, 3));   // phi = pi/2: center + sin
    expect_vec_near(at(p, 50), dvec3(1, 2, -2));  // phi = pi: center - cos
    expect_vec_near(at(p, 75), dvec3(-3, 2, 3));  // phi = 3pi/2: center - sin
}

TEST(Path, OrbitTurnsScalePhase) {
    // Two turns: frame 25 of 100 is phi = pi, half way round.
    const Path p = Orbit{dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), 2};
    expect_vec_near(at(p, 25), dvec3(0, -1, 0));
}

TEST(Path, OrbitWithoutFramesStaysFinite) {
    const Path p = Orbit{dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), 1};
    EXPECT_TRUE(is_finite(at(p, 0, 0)));
}

TEST(Path, TowardIsUnitDirectionFromViewPoint) {
    const Path p = Toward{dvec3(0, 0, 0)};
    expect_vec_near(at(p, 3, 100, dvec3(0, 3, -4)), dvec3(0, -0.6, 0.8));
}

TEST(Path, TowardOwnPointIsZeroNotNaN) {
    const Path p = Toward{dvec3(1, 2, 3)};
    const dvec3 d = at(p, 0, 100, dvec3(1, 2, 3));
    EXPECT_EQ(d, dvec3(0));  // exactly zero, so the movie check reports it
}

TEST(Path, TowardTinyAndHugeOffsetsStayUnit) {
    // length() of these would under/overflow without scaling first.
    const Path tiny = Toward{dvec3(1e-200, 0, 0)};
    expect_vec_near(at(tiny, 0), dvec3(1, 0, 0));
    const Path huge = Toward{dvec3(0, 1e200, 1e200)};
    expect_vec_near(at(huge, 0), dvec3(0, std::sqrt(0.5), std::sqrt(0.5)));
}

TEST(Path, LinearKeyframes) {
    const Path p = keys({{10, dvec3(0, 0, 0)}, {20, dvec3(10, -4, 2)}, {40, dvec3(10, 0, 2)}},
                       Interpolation::linear);
    EXPECT_EQ(at(p, 10), dvec3(0, 0, 0));  // exact at keys
    EXPECT_EQ(at(p, 20), dvec3(10, -4, 2));
    EXPECT_EQ(at(p, 40), dvec3(10, 0, 2));
    expect_vec_near(at(p, 15), dvec3(5, -2, 1));   // midpoint = average
    expect_vec_near(at(p, 30), dvec3(10, -2, 2));  // midpoint of the longer segment
    expect_vec_near(at(p, 35), dvec3(10, -1, 2));  // three quarters
    EXPECT_EQ(at(p, 0), dvec3(0, 0, 0));           // clamps before the first key
    EXPECT_EQ(at(p, 99), dvec3(10, 0, 2));         // and after the last
}

TEST(Path, SingleKeyIsConstant) {
    for (Interpolation interp : {Interpolation::linear, Interpolation::catmull_rom}) {
        const Path p = keys({{5, dvec3(1, 2, 3)}}, interp);
        EXPECT_EQ(at(p, 0), dvec3(1, 2, 3));
        EXPECT_EQ(at(p, 5), dvec3(1, 2, 3));
        EXPECT_EQ(at(p, 80), dvec3(1, 2, 3));
    }
}

TEST(Path, CatmullRomOnCollinearKeysIsLinear) {
    // Values linear in the frame, so every finite-difference tangent is the
    // same slope and the Hermite cubic reduces to the line (even spacing here,
    // uneven in the next test).
    const std::vector<Keyframe> k = {{0, dvec3(0, 0, 0)}, {10, dvec3(2, 4, -6)},
                                     {20, dvec3(4, 8, -12)}, {30, dvec3(6, 12, -18)}};
    const Path cr = keys(k, Interpolation::catmull_rom);
    const Path lin = keys(k, Interpolation::linear);
    for (int f = 0; f <= 30; ++f) expect_vec_near(at(cr, f), at(lin, f));
    expect_vec_near(at(cr, 15), dvec3(3, 6, -9));
}

TEST(Path, CatmullRomOnUnevenCollinearKeysIsLinear) {
    const std::vector<Keyframe> k = {{0, dvec3(0)}, {3, dvec3(3)}, {20, dvec3(20)}};
    const Path cr = keys(k, Interpolation::catmull_rom);
    for (int f = 0; f <= 20; ++f) expect_vec_near(at(cr, f), dvec3(f));
}

TEST(Path, CatmullRomHandWorked) {
    // x keys: 0 @ 0, 10 @ 10, 0 @ 20. Tangents (per frame): m0 = (10-0)/10 = 1
    // (one-sided), m1 = (0-0)/20 = 0, m2 = (0-10)/10 = -1 (one-sided).
    // Frame 5: t = 1/2, h = 10; h00 = h01 = 1/2, h10 = 1/8, h11 = -1/8:
    //   x = 0/2 + (1/8)(10)(1) + 10/2 + (-1/8)(10)(0) = 6.25.
    // Frame 15 by symmetry: 10/2 + 0 + 0/2 + (-1/8)(10)(-1) = 6.25.
    // Frame 2: t = 1/5: h10 = t^3 - 2t^2 + t = 0.008 - 0.08 + 0.2 = 0.128,
    //   h01 = -2t^3 + 3t^2 = 0.104, h11 = t^3 - t^2 = -0.032:
    //   x = 0.128 * 10 * 1 + 0.104 * 10 + 0 = 2.32.
    const Path p = keys({{0, dvec3(0)}, {10, dvec3(10, 0, 0)}, {20, dvec3(0)}},
                        Interpolation::catmull_rom);
    EXPECT_EQ(at(p, 0), dvec3(0));
    EXPECT_EQ(at(p, 10), dvec3(10, 0, 0));
    EXPECT_EQ(at(p, 20), dvec3(0));
    expect_vec_near(at(p, 5), dvec3(6.25, 0, 0));
    expect_vec_near(at(p, 15), dvec3(6.25, 0, 0));
    expect_vec_near(at(p, 2), dvec3(2.32, 0, 0));
    EXPECT_EQ(at(p, -5), dvec3(0));
    EXPECT_EQ(at(p, 25), dvec3(0));
}

TEST(Path, CatmullRomUnevenSpacingHandWorked) {
    // x keys: 0 @ 0, 10 @ 10, 40 @ 30. m0 = 10/10 = 1, m1 = (40-0)/(30-0) = 4/3,
    // m2 = (40-10)/(30-10) = 3/2.
    // Frame 5 (t = 1/2, h = 10): 0 + (1/8)(10)(1) + 10/2 + (-1/8)(10)(4/3) = 55/12.
    // Frame 20 (t = 1/2, h = 20): 10/2 + (1/8)(20)(4/3) + 40/2 + (-1/8)(20)(3/2)
    //   = 5 + 10/3 + 20 - 15/4 = 295/12.
    const Path p = keys({{0, dvec3(0)}, {10, dvec3(10, 0, 0)}, {30, dvec3(40, 0, 0)}},
                        Interpolation::catmull_rom);
    expect_vec_near(at(p, 5), dvec3(55.0 / 12, 0, 0));
    expect_vec_near(at(p, 20), dvec3(295.0 / 12, 0, 0));
}

TEST(Path, AnyFrameSubsetEqualsFullRun) {
    const std::vector<Path> paths = {
        Orbit{dvec3(-10, -10, 16), dvec3(20, 0, 0), dvec3(0, 0, 15), 1.5},
        keys({{0, dvec3(0)}, {7, dvec3(1, 5, 2)}, {19, dvec3(-3, 0, 4)}, {40, dvec3(2)}},
             Interpolation::catmull_rom),
        keys({{3, dvec3(1)}, {17, dvec3(-2, 0, 9)}}, Interpolation::linear),
    };
    for (const Path& p : paths) {
        std::vector<dvec3> full;
        for (int f = 0; f < 300; ++f) full.push_back(at(p, f, 300));
        for (int f = 20; f >= 10; --f) EXPECT_EQ(at(p, f, 300), full[f]);  // bitwise equal
    }
}

}  // namespace
}  // namespace fh
