// orientation(), the edge function of the watertight triangle test: its
// sign is never wrong and it is exactly antisymmetric, on nearly collinear
// inputs where a fused multiply-add would get the sign wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/exact.h"

namespace fh {
namespace {

int sign(double x) { return (x > 0) - (x < 0); }

// Nearly collinear float points p, q: q is p scaled, nudged by an ulp or so.
struct Quad {
    float px, py, qx, qy;
};
Quad near_collinear(std::mt19937& rng) {
    std::uniform_real_distribution<float> coord(-4, 4), scale(0.25f, 4);
    std::uniform_int_distribution<int> nudge(-2, 2);
    const float px = coord(rng), py = coord(rng), s = scale(rng);
    float qx = px * s, qy = py * s;
    for (int k = nudge(rng); k != 0; k += k < 0 ? 1 : -1) qx = std::nextafter(qx, k < 0 ? -8.0f : 8.0f);
    for (int k = nudge(rng); k != 0; k += k < 0 ? 1 : -1) qy = std::nextafter(qy, k < 0 ? -8.0f : 8.0f);
    return {px, py, qx, qy};
}

TEST(Orientation, FloatSignIsNeverWrongAndItIsExactlyAntisymmetric) {
    std::mt19937 rng(5);
    int wrong = 0, not_antisymmetric = 0, fused_wrong = 0, exact_zero_not_zero = 0;
    for (int k = 0; k < 1000000; ++k) {
        const Quad c = near_collinear(rng);
        // Products of floats are exact in double, and so is the sign of their difference.
        const int truth = sign(double(c.px) * c.qy - double(c.py) * c.qx);
        const float o = orientation(c.px, c.py, c.qx, c.qy);
        wrong += sign(o) != 0 && sign(o) != truth;
        exact_zero_not_zero += truth == 0 && o != 0;
        not_antisymmetric += o != -orientation(c.qx, c.qy, c.px, c.py);
        // What a compiler fusing the first product into the difference would give.
        fused_wrong += sign(std::fma(c.px, c.qy, -(c.py * c.qx))) == -truth && truth != 0;
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_EQ(exact_zero_not_zero, 0);
    EXPECT_EQ(not_antisymmetric, 0);
    EXPECT_GT(fused_wrong, 100);  // the inputs are hard enough to catch a fused version
}

// The packet form is the same formula lane by lane.
TEST(Orientation, PacketLanesEqualTheScalarFormula) {
    std::mt19937 rng(6);
    for (int k = 0; k < 10000; ++k) {
        Lanes<float> px, py, qx, qy;
        for (int l = 0; l < kLanes<float>; ++l) {
            const Quad c = near_collinear(rng);
            px[l] = c.px, py[l] = c.py, qx[l] = c.qx, qy[l] = c.qy;
        }
        const Lanes<float> o = orientation(px, py, qx, qy);
        for (int l = 0; l < kLanes<float>; ++l)
            ASSERT_EQ(o[l], orientation(px[l], py[l], qx[l], qy[l])) << k << " lane " << l;
    }
}

// In double: the sign against a compensated reference (the products' exact
// rounding errors added back), where that reference is clearly not zero.
TEST(Orientation, DoubleSignIsNeverWrong) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-4, 4), scale(0.25, 4);
    int wrong = 0, checked = 0;
    for (int k = 0; k < 1000000; ++k) {
        const double px = coord(rng), py = coord(rng), s = scale(rng);
        const double qx = std::nextafter(px * s, 8.0), qy = py * s;
        const double a = px * qy, b = py * qx;
        const double reference = (a - b) + (std::fma(px, qy, -a) - std::fma(py, qx, -b));
        if (std::abs(reference) < 1e-30) continue;
        ++checked;
        const double o = orientation(px, py, qx, qy);
        wrong += sign(o) != 0 && sign(o) != sign(reference);
        EXPECT_EQ(o, -orientation(qx, qy, px, py));
    }
    EXPECT_EQ(wrong, 0);
    EXPECT_GT(checked, 900000);
}

}  // namespace
}  // namespace fh
