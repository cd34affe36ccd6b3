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

inline std::uint8_t to_byte(double v) { return std::uint8_t(std::floor(v + 0.5)); }

// Renders a list of pixels (at most kTileSize^2), spp samples each, a packet
// of samples at a time in pixel order; each sample is clamped on its own
// (SPEC section 4) and the pixel is their mean, rounded. A sample that comes
// out NaN or infinite is counted and contributes black.
template <typename T, typename S>
void render_pixels(const S& shader, const CameraRays<T>& camera, const PixelRef* pixels, int count,
                   int spp, Image& image, RayCounts& counts) {
    constexpr int W = kLanes<T>;
    const StrataGrid grid = strata_for(spp);
    alignas(64) double sum[3][kTileSize * kTileSize];
    for (auto& channel : sum) std::fill_n(channel, count, 0.0);
    int pixel = 0, sample = 0;  // the next sample to take
    const int samples = count * spp;
    for (int first = 0; first < samples; first += W) {
        const int n = std::min(W, samples - first);
        alignas(64) T sx[W], sy[W];
        int pixel_of[W];
        for (int i = 0; i < W; ++i) {
            if (i < n) {
                const PixelRef px = pixels[pixel];
                const SampleOffset o = sample_offset(px.x, px.y, sample, grid);
                sx[i] = T(px.x + o.x);
                sy[i] = T(px.y + o.y);
                pixel_of[i] = pixel;
                if (++sample == spp) sample = 0, ++pixel;
            } else {  // past the last sample: a copy of it, in an inactive lane
                sx[i] = sx[i - 1];
                sy[i] = sy[i - 1];
            }
        }
        const LaneMask<T> active = first_lanes<T>(n);
        counts.primary += std::uint64_t(n);
        const ColorLanes<T> c = shader.trace(camera.generate(load(sx), load(sy)), active, counts);
        const LaneMask<T> ok = finite(c.x) & finite(c.y) & finite(c.z);
        counts.nonfinite_samples += std::uint64_t(fh::count(active & ~ok));
        alignas(64) T clamped[3][W];
        const Lanes<T>* channels[3] = {&c.x, &c.y, &c.z};
        for (int k = 0; k < 3; ++k)
            store(clamped[k], select(ok, min(max(*channels[k], splat(T(0))), splat(T(255))), splat(T(0))));
        if (spp == 1) {  // sample i is pixel first + i: contiguous, vectorised
            for (int k = 0; k < 3; ++k)
                for (int i = 0; i < n; ++i) sum[k][first + i] = double(clamped[k][i]);
        } else {
            for (int i = 0; i < n; ++i)
                for (int k = 0; k < 3; ++k) sum[k][pixel_of[i]] += double(clamped[k][i]);
        }
    }
    // Means to bytes in one loop per channel (vectorised), then into the image.
    std::uint8_t bytes[3][kTileSize * kTileSize];
    for (int k = 0; k < 3; ++k)
        for (int p = 0; p < count; ++p) bytes[k][p] = to_byte(sum[k][p] / double(spp));
    for (int p = 0; p < count; ++p) {
        std::uint8_t* px = image.pixel(pixels[p].x, pixels[p].y);
        for (int k = 0; k < 3; ++k) px[k] = bytes[k][p];
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
    const CameraRays<T> camera_rays(camera);
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
            render_pixels<T>(shader, camera_rays, pixels, n, settings.samples_per_pixel, result.image,
                             counts[size_t(worker)].c);
        });
        if (!settings.adaptive) return;
        const std::vector<PixelRef> refine =
            pixels_to_refine(result.image, settings.adaptive_threshold);
        result.refined_pixels = refine.size();
        const int chunks = int((refine.size() + kChunk - 1) / kChunk);
        run(chunks, [&](int c, int worker) {
            const int n = std::min(kChunk, int(refine.size()) - c * kChunk);
            render_pixels<T>(shader, camera_rays, refine.data() + c * kChunk, n,
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
