// The accuracy knobs: error falls as samples rise, adaptive anti-aliasing
// spends samples only at edges, depth changes only glazed pixels, and the
// error metrics themselves.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>

#include "yaml/scene_loader.h"
#include "render/adaptive.h"
#include "render/packet_intersect.h"
#include "render/image_compare.h"
#include "render/render.h"

namespace fh {
namespace {

// Hard edges: a bright matte sphere on the sunset, seen head-on, 48 x 48.
Scene edge_scene() {
    Scene s;
    Material<double> m;
    m.ambient_color = m.diffuse_color = m.specular_color = {40, 200, 255};
    m.ambient = 0.2;
    m.diffuse = 0.8;
    s.materials = {m};
    s.material_names = {"blue"};
    s.spheres().push_back({{0, 0, 0}, 6, 0});
    s.ambient_lights.push_back({"ambient", {255, 255, 255}, 0.01});
    s.directional_lights.push_back({"sun", {255, 255, 255}, 0.01, glm::normalize(dvec3(-1, 1, -1))});
    Camera c;
    c.projection = Projection::orthographic;
    c.width = c.height = 48;
    c.view_point = {0, -20, 0};
    c.look_at = {0, 1, 0};
    c.up = {0, 0, 1};
    s.cameras = {c};
    return s;
}

FrameResult render_with(const Scene& s, RenderSettings settings, ThreadPool* pool = nullptr) {
    return render_frame(s, s.cameras.front(), settings, pool);
}

RenderSettings samples(int spp) {
    RenderSettings r;
    r.samples_per_pixel = spp;
    return r;
}

TEST(Accuracy, ErrorFallsAsSamplesRise) {
    const Scene s = edge_scene();
    const Image reference = render_with(s, samples(256)).image;
    double previous = 1e9;
    for (int spp : {1, 4, 16, 64}) {
        const double rmse = compare_images(render_with(s, samples(spp)).image, reference).rmse;
        EXPECT_LT(rmse, previous) << spp << " samples";
        previous = rmse;
    }
    EXPECT_LT(previous, 1.0);  // 64 samples: within one step on average
}

TEST(Accuracy, AdaptiveSpendsSamplesOnlyAtEdges) {
    const Scene s = edge_scene();
    const Image reference = render_with(s, samples(256)).image;
    const FrameResult uniform = render_with(s, samples(16));
    RenderSettings a = samples(1);
    a.adaptive = true;
    a.adaptive_samples = 16;
    const FrameResult adaptive = render_with(s, a);
    // The sphere's silhouette: a ring of a few hundred of the 2304 pixels.
    EXPECT_GT(adaptive.refined_pixels, 50u);
    EXPECT_LT(adaptive.refined_pixels, 600u);
    EXPECT_EQ(adaptive.counts.primary, 48u * 48u + adaptive.refined_pixels * 16u);
    EXPECT_LT(double(adaptive.counts.total()), double(uniform.counts.total()) / 3);
    EXPECT_LT(compare_images(adaptive.image, reference).rmse,
              1.25 * compare_images(uniform.image, reference).rmse);
    // The same bytes for any thread count.
    ThreadPool two(2);
    EXPECT_EQ(render_with(s, a, &two).image.rgb, adaptive.image.rgb);
}

// Is the first surface seen through pixel (x, y) glazed?
bool glazed_at(const Scene& s, int x, int y) {
    const auto flat = FlatScene<double>::build(s, plan_effects(s, Effects{}, 5));
    const Ray<double> ray = CameraRays<double>(s.cameras.front()).generate(x + 0.5, y + 0.5);
    const Hit<double> hit = closest_hit(*flat.geometry, ray);
    return hit.found() && flat.shading[size_t(flat.geometry->surface(ray, hit).material)].glazed;
}

TEST(Accuracy, OneMoreLevelOfDepthChangesOnlyGlazedPixels) {
    Scene s = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml").scene;
    Camera cam = *s.find_camera("perspective");
    cam.width = cam.height = 160;
    s.cameras = {cam};
    RenderSettings r;
    r.max_depth = 0;
    FrameResult shallow = render_with(s, r);
    EXPECT_EQ(shallow.counts.reflection, 0u);
    for (int depth = 1; depth <= 4; ++depth) {
        r.max_depth = depth;
        const FrameResult deep = render_with(s, r);
        int changed = 0;
        for (int y = 0; y < cam.height; ++y)
            for (int x = 0; x < cam.width; ++x)
                if (!std::equal(deep.image.pixel(x, y), deep.image.pixel(x, y) + 3,
                                shallow.image.pixel(x, y))) {
                    ++changed;
                    EXPECT_TRUE(glazed_at(s, x, y)) << "depth " << depth << " pixel " << x << "," << y;
                }
        if (depth == 1) EXPECT_GT(changed, 1000);  // the plane, the teal and metal spheres
        shallow = deep;
    }
}

TEST(Accuracy, ErrorMetricsByHand) {
    Image a(2, 1), b(2, 1);
    a.rgb = {10, 20, 30, 40, 50, 60};
    b.rgb = {10, 20, 33, 40, 50, 60};
    const ImageError e = compare_images(a, b);
    EXPECT_NEAR(e.rmse, std::sqrt(9.0 / 6), 1e-12);          // 1.2247
    EXPECT_NEAR(e.psnr, 20 * std::log10(255 / std::sqrt(1.5)), 1e-9);  // 46.37 dB
    EXPECT_EQ(e.max_error, 3);
    EXPECT_DOUBLE_EQ(e.differing, 0.5);
    EXPECT_TRUE(std::isinf(compare_images(a, a).psnr));
}

TEST(Accuracy, RefinesTheNeighbourhoodOfAnEdge) {
    Image img(5, 5);
    std::fill(img.pixel(2, 2), img.pixel(2, 2) + 3, 255);
    const auto refine = pixels_to_refine(img, 8);
    ASSERT_EQ(refine.size(), 9u);  // the white pixel and its 8 neighbours
    EXPECT_EQ(refine.front().x, 1);
    EXPECT_EQ(refine.front().y, 1);
    EXPECT_EQ(refine.back().x, 3);
    EXPECT_EQ(refine.back().y, 3);
    EXPECT_TRUE(pixels_to_refine(img, 255).empty());
}

TEST(Accuracy, RefinesWhatEightNeighboursCheckedOneByOneWouldRefine) {
    // The pass compares each pair of neighbours once, a row of bytes at a
    // time: on random images it must pick the very pixels (and order) that
    // asking each pixel's 8 neighbours, channel by channel, picks --
    // thresholds fractional, at the steps, and outside 0..255 included.
    auto by_hand = [](const Image& img, double threshold) {
        std::vector<std::pair<int, int>> out;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                bool edge = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int nx = x + dx, ny = y + dy;
                        if (nx < 0 || ny < 0 || nx >= img.width || ny >= img.height) continue;
                        for (int c = 0; c < 3; ++c)
                            edge |= std::abs(int(img.pixel(x, y)[c]) - int(img.pixel(nx, ny)[c])) > threshold;
                    }
                if (edge) out.push_back({x, y});
            }
        return out;
    };
    std::mt19937 rng(7);
    for (const auto [w, h] : {std::pair{1, 1}, {1, 6}, {6, 1}, {2, 2}, {7, 3}, {33, 17}})
        for (const int spread : {4, 20, 256}) {  // how far the bytes wander from pixel to pixel
            Image img(w, h);
            const int base = spread == 256 ? 0 : 100;  // the widest: every byte, gaps up to 255
            for (auto& b : img.rgb) b = std::uint8_t(base + int(rng() % unsigned(spread)));
            for (const double threshold : {-1.0, 0.0, 0.5, 3.0, 8.0, 8.5, 19.0, 200.0, 254.5, 255.0, 300.0, std::nan("")}) {
                std::vector<std::pair<int, int>> got;
                for (const PixelRef& p : pixels_to_refine(img, threshold)) got.push_back({p.x, p.y});
                EXPECT_EQ(got, by_hand(img, threshold)) << w << " x " << h << ", spread " << spread
                                                        << ", threshold " << threshold;
            }
        }
}

}  // namespace
}  // namespace fh
