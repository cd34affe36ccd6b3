// unusable_transform (scene/instance.h): which placements the tracer can
// use, each refusal by its reason.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/instance.h"

namespace fh {
namespace {

glm::dmat4 scaled(dvec3 s) { return glm::scale(glm::dmat4(1.0), s); }

TEST(UnusableTransform, ScalesWithinTheLimitsAreUsableMirroredOrNot) {
    EXPECT_EQ(unusable_transform(glm::dmat4(1.0)), "");
    EXPECT_EQ(unusable_transform(scaled({1e12, 1e-12, -1})), "");
    const glm::dmat4 turned = glm::rotate(glm::translate(glm::dmat4(1.0), {1e30, 0, 0}), 1.0, {1.0, 2.0, 3.0});
    EXPECT_EQ(unusable_transform(turned * scaled({2, -3, 0.5})), "");
}

// Lengths of 1e-200 and 1e200: their squares would underflow and overflow.
TEST(UnusableTransform, ScalesPastTheLimitsNameTheScale) {
    const std::string limit = " along an axis; the limit is 1e-12 to 1e12";
    EXPECT_EQ(unusable_transform(scaled({1, 1e-200, 1})), "the transform scales by 1e-200" + limit);
    EXPECT_EQ(unusable_transform(scaled({1, 1, -1e200})), "the transform scales by 1e+200" + limit);
    EXPECT_EQ(unusable_transform(scaled({1.01e12, 1, 1})), "the transform scales by 1.01e+12" + limit);
    // Rotated, the scale is a column's length: 3e-13 * |(0.6, 0.8, 0)|.
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(1.8e-13, 2.4e-13, 0, 0);
    m[1] = glm::dvec4(-0.8, 0.6, 0, 0);
    EXPECT_EQ(unusable_transform(m), "the transform scales by 3e-13" + limit);
}

// Columns of usable lengths in one plane: the third is the sum of the others.
TEST(UnusableTransform, AxesInOnePlaneAreSingular) {
    glm::dmat4 m(1.0);
    m[0] = glm::dvec4(1, 0, 0, 0);
    m[1] = glm::dvec4(0, 2, 0, 0);
    m[2] = glm::dvec4(1, 2, 0, 0);
    EXPECT_EQ(unusable_transform(m), "the transform is singular (it flattens space: no inverse)");
    m[2] = glm::dvec4(1, 2, 1e-9, 0);  // nearly, but an inverse exists
    EXPECT_EQ(unusable_transform(m), "");
    EXPECT_EQ(unusable_transform(scaled({1, 0, 1})), "the transform is singular (it flattens space: no inverse)");
}

// Columns of usable lengths, not in one plane, whose inverse carries a
// direction 3.3e23 times longer (a group scaled by 2e-12 along y around an
// instance scaled by 1.5e-12 and turned 45 degrees): the float tracer would
// square that past 1e38.
TEST(UnusableTransform, AnInverseBeyondTheLimitsIsRefused) {
    const glm::dmat4 m = scaled({1, 2e-12, 1}) * glm::rotate(glm::dmat4(1.0), M_PI / 4, {0.0, 0.0, 1.0}) *
                         scaled({1.5e-12, 1.5e-12, 1});
    EXPECT_NEAR(glm::length(dvec3(m[0])), 1.06e-12, 0.01e-12);
    EXPECT_EQ(unusable_transform(m), "the transform scales by 3e-24 along an axis; the limit is 1e-12 to 1e12");
}

// What a movie's frame does with a composed transform: keeps exactly those
// unusable_transform accepts (its quick test included), the others become
// the zero map.
TEST(UnusableTransform, AFramesInstanceIsKeptExactlyWhenUsable) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1), exponent(-14, 14);
    int kept = 0, dropped = 0;
    for (int i = 0; i < 20000; ++i) {
        glm::dmat4 m(1.0);
        for (int c = 0; c < 3; ++c) m[c] = glm::dvec4(u(rng), u(rng), u(rng), 0) * std::pow(10.0, exponent(rng) * (i % 3 == 0));
        if (i % 7 == 0) m[2] = m[0] + 1e-13 * m[1];  // nearly in one plane
        m[3] = glm::dvec4(u(rng), u(rng), u(rng), 1);
        const bool usable = unusable_transform(m).empty();
        const glm::dmat4 placed = usable_or_nothing(m);
        EXPECT_EQ(placed == m, usable) << i;
        if (!usable) EXPECT_EQ(placed[0], glm::dvec4(0)) << i;
        (usable ? kept : dropped)++;
    }
    EXPECT_GT(kept, 5000);
    EXPECT_GT(dropped, 3000);
}

TEST(UnusableTransform, NotFiniteIsSaid) {
    glm::dmat4 m(1.0);
    m[3][1] = std::nan("");
    EXPECT_EQ(unusable_transform(m), "the transform is not finite");
    m[3][1] = INFINITY;
    EXPECT_EQ(unusable_transform(m), "the transform is not finite");
}

}  // namespace
}  // namespace fh
