#include "render/render.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

#include "render/adaptive.h"
#include "render/sampler.h"
#include "render/shading.h"

namespace fh {

namespace {

// One sample: clamp each sample on its own (SPEC section 4); a non-finite one
// is counted and contributes black.
template <typename T>
inline Color<T> clamped(Color<T> c, RayCounts& counts) {
    if (!is_finite(c)) {
        ++counts.nonfinite_samples;
        return Color<T>(0);
    }
    return glm::clamp(c, Color<T>(0), Color<T>(255));
}

inline std::uint8_t to_byte(double v) { return std::uint8_t(std::floor(v + 0.5)); }

// Renders a list of pixels (at most kTileSize^2), spp samples each, through
// the shader in batches, in pixel order; each sample is clamped on its own
// and the pixel is their mean, rounded.
template <typename T, typename S>
void render_pixels(const S& shader, const CameraRays<T>& rays, const PixelRef* pixels, int count,
                   int spp, Image& image, RayCounts& counts) {
    const StrataGrid grid = strata_for(spp);
    constexpr int kBatch = RayBatch<T>::kCapacity;
    Color<double> sum[kTileSize * kTileSize];
    RayBatch<T> batch;
    Color<T> colour[kBatch];
    int pixel_of[kBatch];  // which listed pixel each ray of the batch samples
    T sample_x[kBatch], sample_y[kBatch];
    int n = 0;
    auto flush = [&] {
        rays.generate(sample_x, sample_y, n, batch);
        counts.primary += std::uint64_t(n);
        shader.trace(batch, colour, counts);  // leaves batch holding its last wave
        for (int i = 0; i < n; ++i) sum[pixel_of[i]] += Color<double>(clamped(colour[i], counts));
        n = 0;
    };
    auto add_sample = [&](int p, double x, double y) {
        pixel_of[n] = p;
        sample_x[n] = T(x);
        sample_y[n] = T(y);
        if (++n == kBatch) flush();
    };
    for (int p = 0; p < count; ++p) sum[p] = Color<double>(0);
    if (spp == 1) {  // the centre: no hashing (its own loop, so none is done speculatively)
        for (int p = 0; p < count; ++p) add_sample(p, pixels[p].x + 0.5, pixels[p].y + 0.5);
    } else {
        for (int p = 0; p < count; ++p) {
            const int x = pixels[p].x, y = pixels[p].y;
            for (int s = 0; s < spp; ++s) {
                const SampleOffset o = sample_offset(x, y, s, grid);
                add_sample(p, x + o.x, y + o.y);
            }
        }
    }
    if (n > 0) flush();
    for (int p = 0; p < count; ++p) {
        const Color<double> mean = sum[p] / double(spp);
        std::uint8_t* px = image.pixel(pixels[p].x, pixels[p].y);
        px[0] = to_byte(mean.r);
        px[1] = to_byte(mean.g);
        px[2] = to_byte(mean.b);
    }
}

// The pixels of tile t, in row order.
int tile_pixels(int t, int width, int height, PixelRef* out) {
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int x0 = (t % tiles_x) * kTileSize, y0 = (t / tiles_x) * kTileSize;
    int n = 0;
    for (int y = y0; y < std::min(y0 + kTileSize, height); ++y)
        for (int x = x0; x < std::min(x0 + kTileSize, width); ++x)
            out[n++] = {std::uint16_t(x), std::uint16_t(y)};
    return n;
}

template <typename T>
FrameResult render_with(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                        const Effects& effects, ThreadPool* pool) {
    const auto start = std::chrono::steady_clock::now();
    const FlatScene<T> flat = FlatScene<T>::build(
        scene, plan_effects(scene, effects, settings.max_depth, settings.prune));
    const CameraRays<T> rays(camera);
    FrameResult result;
    result.image = Image(camera.width, camera.height);
    result.plan = flat.plan;

    // One counter block per worker, a cache line apart so they do not share one.
    struct alignas(64) PaddedCounts {
        RayCounts c;
    };
    std::vector<PaddedCounts> counts(static_cast<size_t>(pool ? pool->size() : 1));
    auto run = [&](int tasks, const std::function<void(int, int)>& fn) {
        if (pool) pool->parallel_for(tasks, fn);
        else for (int t = 0; t < tasks; ++t) fn(t, 0);
    };
    constexpr int kChunk = kTileSize * kTileSize;
    with_shader(flat, [&](const auto& shader) {
        const int tiles = ((camera.width + kTileSize - 1) / kTileSize) *
                          ((camera.height + kTileSize - 1) / kTileSize);
        run(tiles, [&](int t, int worker) {
            PixelRef pixels[kChunk];
            const int n = tile_pixels(t, camera.width, camera.height, pixels);
            render_pixels<T>(shader, rays, pixels, n, settings.samples_per_pixel, result.image,
                             counts[size_t(worker)].c);
        });
        if (!settings.adaptive) return;
        const std::vector<PixelRef> refine =
            pixels_to_refine(result.image, settings.adaptive_threshold);
        result.refined_pixels = refine.size();
        const int chunks = int((refine.size() + kChunk - 1) / kChunk);
        run(chunks, [&](int c, int worker) {
            const int n = std::min(kChunk, int(refine.size()) - c * kChunk);
            render_pixels<T>(shader, rays, refine.data() + c * kChunk, n,
                             settings.adaptive_samples, result.image, counts[size_t(worker)].c);
        });
    });
    for (const auto& c : counts) result.counts += c.c;
    result.render_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace

FrameResult render_frame(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                         const Effects& effects, ThreadPool* pool) {
    if (settings.precision == Precision::single)
        return render_with<float>(scene, camera, settings, effects, pool);
    return render_with<double>(scene, camera, settings, effects, pool);
}

}  // namespace fh
