// The report's scene scaled by 1000 and moved by
// (1e4, 1e4, 1e4), camera too, renders the same picture.
//
// The transform x -> 1000 x + (1e4, 1e4, 1e4) is applied to every position
// (sphere centres and radii, triangle vertices, the spot light, the view
// point) and to each plane's distance (n.x = d becomes n.x = 1000 d + n.t).
// Directions (normals, look_at, up, the lights' directions) stay. The spot
// light falls off with d^2, so its intensity is multiplied by 1e6; the
// directional and ambient lights stay. The perspective camera's image plane
// is fixed (half-height 10 at projection distance 10), so the same look_at
// direction from the scaled view point frames the same picture.
//
// Stated tolerance, per precision, over the 800x800 frame of the report's
// perspective camera (400x400 under the sanitizers), for each set of lights:
// at most 0.01% of the pixels (64)
// differ by more than 2 on any channel -- pixels whose centre lies within
// rounding of a silhouette or shadow edge -- and the mean absolute difference
// over all channels is below 0.01. (Measured: in double the images are
// identical; in float 0 to 2 pixels differ by more than 2, mean below 0.001.)
#include <gtest/gtest.h>

#include <cmath>

#include "yaml/scene_loader.h"
#include "robust_util.h"

namespace fh {
namespace {

using namespace fh::robust;

template <typename T>
class ScaleInvariance : public ::testing::Test {};
TYPED_TEST_SUITE(ScaleInvariance, Scalars);

constexpr double kScale = 1000;
const dvec3 kShift(1e4, 1e4, 1e4);

dvec3 move(const dvec3& p) { return kScale * p + kShift; }

Scene transformed(Scene s) {
    for (auto& sp : s.spheres()) {
        sp.center = move(sp.center);
        sp.radius *= kScale;
    }
    for (auto& p : s.planes) p.distance = kScale * p.distance + glm::dot(p.normal, kShift);
    for (auto& t : s.triangles) {
        const dvec3 a = t.v0, b = t.v1, c = t.v2;
        t = Triangle<double>::make(move(a), move(b), move(c), t.material);
    }
    for (auto& l : s.spot_lights) {
        l.position = move(l.position);
        l.intensity *= kScale * kScale;
    }
    for (auto& c : s.cameras) c.view_point = move(c.view_point);
    return s;
}

TYPED_TEST(ScaleInvariance, ReportSceneScaledAndMoved) {
    using T = TypeParam;
    const Scene original = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml").scene;
    const Scene moved = transformed(original);
    // Also with each light on its own, so a shadow or highlight lost to one
    // light cannot hide under another's saturation.
    const std::vector<std::vector<std::string>> light_sets = {
        {"ambient", "directional", "spot"}, {"ambient", "spot"}, {"ambient", "directional"}};
    for (const auto& lights : light_sets) {
        Scene a = original, b = moved;
        keep_only_lights(a, lights);
        keep_only_lights(b, lights);
        // Under the sanitizers, the same picture at 400 x 400 (the image plane
        // is fixed, so only the sampling changes): a quarter of the work.
        for (Scene* sc : {&a, &b})
            for (Camera& c : sc->cameras) c.width = c.height = kSanitized ? 400 : 800;
        const auto ra = render(a, *a.find_camera("perspective"), precision_of<T>(), Effects{});
        const auto rb = render(b, *b.find_camera("perspective"), precision_of<T>(), Effects{});
        expect_finite_frame(ra, "report scene");
        expect_finite_frame(rb, "report scene, x1000 and moved");
        EXPECT_EQ(ra.counts.primary, rb.counts.primary);
        const Image& x = ra.image;
        const Image& y = rb.image;
        ASSERT_EQ(x.rgb.size(), y.rgb.size());
        long total = 0;
        int off_pixels = 0;
        for (int py = 0; py < x.height; ++py)
            for (int px = 0; px < x.width; ++px) {
                bool off = false;
                for (int c = 0; c < 3; ++c) {
                    const int d = std::abs(int(x.pixel(px, py)[c]) - int(y.pixel(px, py)[c]));
                    total += d;
                    off = off || d > 2;
                }
                off_pixels += off;
            }
        const double pixels = double(x.width) * x.height;
        const double mean = double(total) / (3 * pixels);
        std::string set;
        for (const auto& l : lights) set += l + " ";
        EXPECT_LE(off_pixels, 1e-4 * pixels) << "lights: " << set;
        EXPECT_LT(mean, 0.01) << "lights: " << set;
        // Shadow and reflection rays alike: the same number of each, to a few
        // rays on boundaries.
        EXPECT_NEAR(double(ra.counts.shadow), double(rb.counts.shadow), 1e-3 * double(ra.counts.shadow));
        EXPECT_NEAR(double(ra.counts.reflection), double(rb.counts.reflection),
                    1e-3 * double(ra.counts.reflection));
    }
}

}  // namespace
}  // namespace fh
