// Two facing mirrors. Every reflection ray finds the other
// mirror, so only max_depth ends the chain: exactly max_depth reflection rays
// per primary ray, and a finite colour equal to the geometric series.
#include <gtest/gtest.h>

#include <cmath>

#include "robust_util.h"

namespace fh {
namespace {

using namespace fh::robust;

template <typename T>
class Mirrors : public ::testing::Test {};
TYPED_TEST_SUITE(Mirrors, Scalars);

constexpr int kSize = 24;

// The planes x = -1 and x = +1, glazed with `reflectivity`, lit by an ambient
// light only: each surface adds ambient = (3, 2, 1) * `brightness`.
Scene mirrors(double reflectivity, double brightness, bool lights = false) {
    Scene s;
    const int m = add_material(s, "mirror", material({3, 2, 1}, 1, 0.5, 1, 10, true, reflectivity));
    s.planes.push_back({{1, 0, 0}, 1, m});    // x = 1
    s.planes.push_back({{-1, 0, 0}, 1, m});   // x = -1 (n.x = d with n = -x)
    s.ambient_lights.push_back({"a", {255, 255, 255}, brightness / 255});
    if (lights) {
        s.directional_lights.push_back({"d", {255, 255, 255}, 0.5, glm::normalize(dvec3(1, 1, -1))});
        s.spot_lights.push_back({"s", {255, 255, 255}, 2, {0, 0, 0.5}, {1, 0, 0}, 1.0});
    }
    return s;
}

TYPED_TEST(Mirrors, RecursionStopsAtMaxDepthWithTheSeriesValue) {
    using T = TypeParam;
    struct Case {
        double reflectivity, brightness;
        int depth;
    };
    for (const Case c : {Case{0.5, 30, 0}, Case{0.5, 30, 1}, Case{0.5, 30, 5}, Case{0.5, 30, 64},
                         Case{1.0, 1, 64}, Case{1.0, 1, 5}}) {
        const Scene s = mirrors(c.reflectivity, c.brightness);
        // Orthographic along +x: every ray bounces on one line, back and forth.
        // Perspective, 45 degrees each side of +x: zig-zags, all hitting.
        for (const auto proj : {Projection::orthographic, Projection::perspective}) {
            const Camera cam = camera(proj, {0.25, 0, 0}, {1, 0, 0}, {0, 0, 1}, kSize);
            const auto r = render(s, cam, precision_of<T>(), all_effects(), c.depth);
            expect_finite_frame(r, "mirrors");
            EXPECT_EQ(r.counts.primary, std::uint64_t(kSize * kSize));
            EXPECT_EQ(r.counts.reflection, std::uint64_t(kSize * kSize) * std::uint64_t(c.depth))
                << "depth " << c.depth;
            // ambient * (1 + r + ... + r^depth) on each channel.
            double series = 0;
            for (int k = 0; k <= c.depth; ++k) series += std::pow(c.reflectivity, k);
            for (int y = 0; y < kSize; y += 5)
                for (int x = 0; x < kSize; x += 5)
                    for (int ch = 0; ch < 3; ++ch) {
                        const double want = std::min(255.0, (3 - ch) * c.brightness * series);
                        EXPECT_NEAR(int(r.image.pixel(x, y)[ch]), want, 1.0)
                            << "depth " << c.depth << " reflectivity " << c.reflectivity;
                    }
        }
    }
}

// With every light and effect on, at the deepest chain allowed, and the
// camera on a mirror's plane (rays starting in the plane, grazing it).
TYPED_TEST(Mirrors, AllEffectsDeepestChainIsFinite) {
    using T = TypeParam;
    const Scene s = mirrors(1.0, 1, true);
    for (const dvec3 eye : {dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(-1, 0.5, 0.25)}) {
        const auto r = render(s, camera(Projection::perspective, eye, {1, 0.3, 0.1}, {0, 0, 1}, kSize),
                              precision_of<T>(), all_effects(), Limits::max_depth);
        expect_finite_frame(r, "mirrors, all effects");
        EXPECT_LE(r.counts.reflection, std::uint64_t(kSize * kSize) * Limits::max_depth);
    }
}

}  // namespace
}  // namespace fh
