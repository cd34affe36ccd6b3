// A packet is only a faster way to trace its rays: every pixel of
// render_frame -- packets of different rays, partial packets at a row's end,
// tiles that skip what their frustum cannot reach, primitives blended into
// the lanes that hit them -- is that pixel's rays traced one at a time.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "yaml/scene_loader.h"
#include "render/levels.h"
#include "render/render.h"
#include "render/sampler.h"
#include "render/shading.h"

namespace fh {
namespace {

// The pixel bytes render_frame should give, from rays traced one by one:
// each sample clamped (NaN: black), the mean of a pixel's samples rounded.
// The scenes have no instances: only the shader variants without them are
// compiled here (with_shader's instanced ones doubled this file's build).
template <typename T>
Image one_ray_at_a_time(const Scene& scene, const Camera& camera, int spp) {
    const auto flat = FlatScene<T>::build(scene, plan_effects(scene, Effects{}, 5));
    if (flat.instances) throw std::logic_error("one_ray_at_a_time: a scene with instances");
    const CameraRays<T> rays(camera);
    const StrataGrid grid = strata_for(spp);
    Image image(camera.width, camera.height);
    with_shader_of<T, false>(flat, [&](const auto& shader) {
        RayCounts counts;
        for (int y = 0; y < camera.height; ++y)
            for (int x = 0; x < camera.width; ++x) {
                double sum[3] = {0, 0, 0};
                for (int s = 0; s < spp; ++s) {
                    const SampleOffset o = sample_offset(x, y, s, grid);
                    const Color<T> c = shader.trace(rays.generate(T(x + o.x), T(y + o.y)), counts);
                    for (int k = 0; k < 3; ++k)
                        sum[k] += std::isfinite(c[k]) ? std::min(std::max(double(c[k]), 0.0), 255.0) : 0.0;
                }
                for (int k = 0; k < 3; ++k)
                    image.pixel(x, y)[k] = std::uint8_t(std::floor(sum[k] / spp + 0.5));
            }
    }, {});
    return image;
}

template <typename T>
void expect_same_as_one_ray_at_a_time(const Scene& scene, const Camera& camera, int spp) {
    // render_frame runs the tracer of the level FIRSTHIT_ISA picks; the one
    // ray at a time, this binary's own copy (FIRSTHIT_TRACER_LEVEL). In
    // float they agree only at the same level: FMA (v3, v4) rounds once
    // where v2 rounds twice. Double agrees at every level.
    if (std::is_same_v<T, float> && level_in_use() != FIRSTHIT_TRACER_LEVEL) return;
    RenderSettings settings;
    settings.samples_per_pixel = spp;
    settings.precision = std::is_same_v<T, float> ? Precision::float32 : Precision::float64;
    ThreadPool pool(2);
    const Image packets = render_frame(scene, camera, settings, &pool).image;
    const Image expected = one_ray_at_a_time<T>(scene, camera, spp);
    int differing = 0;
    for (size_t i = 0; i < packets.rgb.size(); ++i) differing += packets.rgb[i] != expected.rgb[i];
    EXPECT_EQ(differing, 0) << camera.name << ", " << spp << " spp, " << (sizeof(T) == 4 ? "float" : "double");
}

// 97 x 61: rows end in partial packets and partial tiles, both ways.
Camera small(Camera c) {
    c.width = 97;
    c.height = 61;
    return c;
}

TEST(Packets, RenderFrameIsEachPixelsRaysTracedOneAtATime) {
    const Scene scene = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml").scene;
    // 2, 4 and 8 samples: several whole pixels a packet (but 8 in double, 8
    // lanes: one pixel a packet); 16: one pixel's samples a packet, or two;
    // 3, 6 and 24: packets that end inside a pixel, strata of 3 x 1, 3 x 2
    // and 6 x 4. Every lane's cell at once in each.
    for (const Camera& camera : scene.cameras)
        for (const int spp : {1, 2, 3, 4, 6, 8, 16, 24}) {
            expect_same_as_one_ray_at_a_time<double>(scene, small(camera), spp);
            expect_same_as_one_ray_at_a_time<float>(scene, small(camera), spp);
        }
}

TEST(Packets, RefiningWithOneSampleRendersTheCentresAgain) {
    // Adaptive anti-aliasing with one sample a refined pixel: the refined
    // pixels' one sample is their centre, as in the first pass.
    const Scene scene = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml").scene;
    RenderSettings one, refined;
    refined.adaptive = true;
    refined.adaptive_samples = 1;
    const Camera camera = small(scene.cameras.front());
    const FrameResult r = render_frame(scene, camera, refined, nullptr);
    EXPECT_GT(r.refined_pixels, 100u);
    EXPECT_EQ(r.image.rgb, render_frame(scene, camera, one, nullptr).image.rgb);
}

TEST(Packets, SameWithANarrowSpotCone) {
    // Figure 6: the spot light's cone test on, lanes on both sides of its edge.
    const Scene scene = load_scene(FIRSTHIT_SOURCE_DIR "/animations/figures/figure6.yaml").scene;
    expect_same_as_one_ray_at_a_time<double>(scene, small(scene.cameras.front()), 1);
    expect_same_as_one_ray_at_a_time<float>(scene, small(scene.cameras.front()), 1);
}

}  // namespace
}  // namespace fh
