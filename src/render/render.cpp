#include "render/render.h"

#include <algorithm>
#include <chrono>
#include <cmath>

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

// A tile's samples go through the shader in batches, in pixel order; each
// sample is clamped on its own and the pixel is their mean, rounded.
template <typename T, typename S>
void render_tile(const S& shader, const CameraRays<T>& rays, int spp, int x0, int y0, int x1,
                 int y1, Image& image, RayCounts& counts) {
    const StrataGrid grid = strata_for(spp);
    constexpr int kBatch = RayBatch<T>::kCapacity;
    Color<double> sum[kTileSize * kTileSize];
    RayBatch<T> batch;
    Color<T> colour[kBatch];
    int pixel_of[kBatch];  // which pixel of the tile each ray of the batch samples
    auto flush = [&] {
        const int n = batch.size;
        counts.primary += std::uint64_t(n);
        shader.trace(batch, colour, counts);  // leaves batch holding its last wave
        for (int i = 0; i < n; ++i) sum[pixel_of[i]] += Color<double>(clamped(colour[i], counts));
        batch.size = 0;
    };
    int p = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x, ++p) {
            sum[p] = Color<double>(0);
            for (int s = 0; s < spp; ++s) {
                const SampleOffset o = sample_offset(x, y, s, grid);
                pixel_of[batch.size] = p;
                batch.push(rays.generate(T(x + o.x), T(y + o.y)));
                if (batch.full()) flush();
            }
        }
    }
    if (batch.size > 0) flush();
    p = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x, ++p) {
            const Color<double> mean = sum[p] / double(spp);
            std::uint8_t* px = image.pixel(x, y);
            px[0] = to_byte(mean.r);
            px[1] = to_byte(mean.g);
            px[2] = to_byte(mean.b);
        }
    }
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

    const int tiles_x = (camera.width + kTileSize - 1) / kTileSize;
    const int tiles_y = (camera.height + kTileSize - 1) / kTileSize;
    const int workers = pool ? pool->size() : 1;
    // One counter block per worker, a cache line apart so they do not share one.
    struct alignas(64) PaddedCounts {
        RayCounts c;
    };
    std::vector<PaddedCounts> counts(static_cast<size_t>(workers));
    with_shader(flat, [&](const auto& shader) {
        auto tile = [&](int t, int worker) {
            const int x0 = (t % tiles_x) * kTileSize;
            const int y0 = (t / tiles_x) * kTileSize;
            render_tile<T>(shader, rays, settings.samples_per_pixel, x0, y0,
                           std::min(x0 + kTileSize, camera.width),
                           std::min(y0 + kTileSize, camera.height), result.image,
                           counts[size_t(worker)].c);
        };
        if (pool) {
            pool->parallel_for(tiles_x * tiles_y, tile);
        } else {
            for (int t = 0; t < tiles_x * tiles_y; ++t) tile(t, 0);
        }
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
