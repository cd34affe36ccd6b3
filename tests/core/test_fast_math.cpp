// Shading's branch-free acos and whole powers against the library
// functions they replace, over their whole domains.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/fast_math.h"

namespace fh {
namespace {

constexpr double kPi = 3.14159265358979323846;

template <typename T>
class FastMath : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(FastMath, Scalars);

TYPED_TEST(FastMath, AcosIsWithinAFewUlpsOfPiEverywhere) {
    using T = TypeParam;
    const double ulp_of_pi = std::numeric_limits<T>::epsilon() * 4;  // ulp(pi) = 2 eps; allow 2 of them
    double worst = 0;
    for (int k = -200000; k <= 200000; ++k) {
        const T x = T(k / 200000.0);
        const double exact = std::acos(double(x));
        worst = std::max(worst, std::abs(double(acos_fast(x)) - exact));
    }
    EXPECT_LE(worst, ulp_of_pi);
}

TYPED_TEST(FastMath, AcosAtTheSeamsAndEnds) {
    using T = TypeParam;
    const T eps = std::numeric_limits<T>::epsilon();
    // The exact values, and the branch seams at |x| = 1/2 from both sides.
    EXPECT_EQ(acos_fast(T(1)), T(0));
    EXPECT_NEAR(double(acos_fast(T(-1))), kPi, 2 * eps * kPi);
    EXPECT_NEAR(double(acos_fast(T(0))), kPi / 2, 2 * eps * kPi);
    EXPECT_NEAR(double(acos_fast(T(0.5))), kPi / 3, 2 * eps * kPi);
    EXPECT_NEAR(double(acos_fast(T(-0.5))), 2 * kPi / 3, 2 * eps * kPi);
    for (const T x : {std::nextafter(T(0.5), T(0)), std::nextafter(T(0.5), T(1)),
                      std::nextafter(T(1), T(0)), std::nextafter(T(-1), T(0))})
        EXPECT_NEAR(double(acos_fast(x)), std::acos(double(x)), 2 * eps * kPi) << x;
    EXPECT_TRUE(std::isnan(acos_fast(std::numeric_limits<T>::quiet_NaN())));
}

// x^n by every step from the top bit kWholePowerLimit has (12): the steps the
// shader takes for the largest exponent there can be.
template <typename T>
T pow_whole(T x, T n) {
    T r = 1;
    for (int bit = 11; bit >= 0; --bit) pow_whole_step(r, x, n, bit);
    return r;
}

TYPED_TEST(FastMath, WholePowersMatchStdPow) {
    using T = TypeParam;
    const T eps = std::numeric_limits<T>::epsilon();
    for (const int n : {0, 1, 2, 3, 7, 10, 79, 100, 255, 1000, 4095}) {
        for (const T x : {T(0), T(0.25), T(0.5), T(0.9), T(0.999), T(1)}) {
            const double exact = std::pow(double(x), n);
            // Each squaring doubles the relative error so far: ~n eps in all,
            // as for any product of n roundings; below the smallest normal T, 0.
            EXPECT_NEAR(double(pow_whole(x, T(n))), exact, (2 * n + 24) * eps * exact + std::numeric_limits<T>::min())
                << x << "^" << n;
        }
    }
    EXPECT_EQ(pow_whole(T(0), T(0)), T(1));  // as std::pow
}

TYPED_TEST(FastMath, PowerStepsFromTheTopBitAgree) {
    using T = TypeParam;
    // The shader runs only as many steps as the largest exponent has bits.
    for (const int n : {5, 79, 100}) {
        T r = 1, left = T(n);
        for (int bit = 6; bit >= 0; --bit) pow_whole_step(r, T(0.97), left, bit);
        EXPECT_EQ(left, T(0));
        EXPECT_EQ(r, pow_whole(T(0.97), T(n))) << n;
    }
}

}  // namespace
}  // namespace fh
