// render_frame_as<T> (render/render.h) in one scalar type: the tiles, the
// packets of camera rays, the pixels. Only render.cpp (double) and
// render_float.cpp (float) include this, each compiling one precision's
// shader variants -- the project's longest compile, split over two files so
// that two cores share it.
#pragma once

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <utility>

#include "render/adaptive.h"
#include "render/render.h"
#include "render/sampler.h"
#include "render/shading.h"
#include "render/tile_culling.h"

namespace fh {


namespace detail {

inline std::uint8_t to_byte(double v) { return std::uint8_t(std::floor(v + 0.5)); }

// A packet's lanes widened to double, as 32-bit integers (signed and not),
// as bytes and as 64-bit seeds.
template <typename T>
struct WideLanes {
    typedef double Doubles __attribute__((vector_size(kLanes<T> * sizeof(double))));
    typedef std::int32_t Ints __attribute__((vector_size(kLanes<T> * sizeof(std::int32_t))));
    typedef std::uint8_t Bytes __attribute__((vector_size(kLanes<T>)));
    typedef std::uint32_t Uints __attribute__((vector_size(kLanes<T> * sizeof(std::uint32_t))));
    typedef std::uint64_t Seeds __attribute__((vector_size(kLanes<T> * sizeof(std::uint64_t))));
};

// to_byte of each lane of a clamped channel, as vector conversions: in
// [0, 255], floor(v + 0.5) is the truncation, and the sum is taken in double
// (in float, v + 0.5 would round first), so the bytes are to_byte's.
template <typename T>
FH_HOT_INLINE typename WideLanes<T>::Bytes to_bytes(const Lanes<T>& v) {
    using W = WideLanes<T>;
    const typename W::Doubles d = __builtin_convertvector(v, typename W::Doubles) + 0.5;
    return __builtin_convertvector(__builtin_convertvector(d, typename W::Ints), typename W::Bytes);
}

// A whole block's bytes in the image's order -- R G B of each pixel, the
// block's rows one after another -- by shuffles, not 3 W single-byte
// moves: bytes[ch] lane k is channel ch of the block's pixel k, and byte
// 3k + ch of the result is that (the last W bytes are padding).
template <int W, size_t... K>  // K: 0 .. 4 W - 1
FH_HOT_INLINE auto pick_rgb(const auto& rg, const auto& bb, std::index_sequence<K...>) {
    return __builtin_shufflevector(rg, bb, (K < 3 * W ? (K % 3) * W + K / 3 : 0)...);
}
template <int W, typename Bytes, size_t... K>  // K: 0 .. 2 W - 1
FH_HOT_INLINE auto interleave_rgb(const Bytes (&bytes)[3], std::index_sequence<K...>) {
    // Red then green, and blue twice: byte ch W + k of the pair is bytes[ch][k].
    const auto rg = __builtin_shufflevector(bytes[0], bytes[1], K...);
    const auto bb = __builtin_shufflevector(bytes[2], bytes[2], (K % W)...);
    return pick_rgb<W>(rg, bb, std::make_index_sequence<4 * W>{});
}

// The clamped colour of each sample (docs/model.md section 4), lane by lane; a sample
// that came out NaN or infinite is counted and contributes black.
template <typename T>
FH_HOT_INLINE ColorLanes<T> clamp_samples(const ColorLanes<T>& c, const LaneInts<T>& active,
                                          RayCounts& counts) {
    const LaneInts<T> ok = finite(c.x) & finite(c.y) & finite(c.z);
    counts.nonfinite_samples += std::uint64_t(fh::count(active & ~ok));
    auto clamp = [&ok](const Lanes<T>& v) FH_HOT_LAMBDA {
        return select(ok, min(max(v, splat(T(0))), splat(T(255))), splat(T(0)));
    };
    return {clamp(c.x), clamp(c.y), clamp(c.z)};
}

// Where a packet holds W / G whole pixels of G samples each (G < W): each
// pixel's sum, its samples added in lane order from the first as the
// pixel-by-pixel loop adds them (the same bytes), for every pixel at once.
template <int G, size_t K, size_t... J>  // sample K of each pixel; J: 0 .. W / G - 1
FH_HOT_INLINE auto pixels_sample(const auto& samples, std::index_sequence<J...>) {
    return __builtin_shufflevector(samples, samples, (J * G + K)...);
}
template <int G, size_t... K>  // K: 0 .. G - 2
FH_HOT_INLINE auto pixel_sums(const auto& samples, std::index_sequence<K...>) {
    constexpr auto pixels = std::make_index_sequence<sizeof(samples) / sizeof(samples[0]) / G>{};
    auto sum = pixels_sample<G, 0>(samples, pixels);
    ((sum += pixels_sample<G, K + 1>(samples, pixels)), ...);
    return sum;
}

// Those pixels' bytes, written to the image: to_byte of each mean.
template <typename T, int G>
FH_HOT_INLINE void write_pixel_means(const ColorLanes<T>& c, const PixelRef* pixels, Image& image) {
    using W = WideLanes<T>;
    constexpr int kPixels = kLanes<T> / G;
    typedef std::int32_t Bytes __attribute__((vector_size(kPixels * sizeof(std::int32_t))));
    alignas(64) std::int32_t bytes[3][kPixels];
    const Lanes<T>* channels[3] = {&c.x, &c.y, &c.z};
    for (int k = 0; k < 3; ++k) {
        const auto sum = pixel_sums<G>(__builtin_convertvector(*channels[k], typename W::Doubles),
                                       std::make_index_sequence<G - 1>{});
        const Bytes b = __builtin_convertvector(sum / double(G) + 0.5, Bytes);
        std::memcpy(bytes[k], &b, sizeof b);
    }
    for (int j = 0; j < kPixels; ++j) {
        std::uint8_t* px = image.pixel(pixels[j].x, pixels[j].y);
        for (int k = 0; k < 3; ++k) px[k] = std::uint8_t(bytes[k][j]);
    }
}
// The same for spp samples a pixel, where a packet holds whole pixels of 2,
// 4 or 8 samples; false (nothing written) for any other count.
template <typename T>
FH_HOT_INLINE bool write_whole_pixels(int spp, const ColorLanes<T>& c, const PixelRef* pixels, Image& image) {
    constexpr int W = kLanes<T>;
    if constexpr (W > 2)
        if (spp == 2) return write_pixel_means<T, 2>(c, pixels, image), true;
    if constexpr (W > 4)
        if (spp == 4) return write_pixel_means<T, 4>(c, pixels, image), true;
    if constexpr (W > 8)
        if (spp == 8) return write_pixel_means<T, 8>(c, pixels, image), true;
    return false;
}

// One sample through each pixel's centre, for the pixels [x0, x1) x [y0, y1)
// of one tile (at most kTileSize square):
// a packet is a block of neighbouring pixels -- 4 wide and W / 4 high (4 x 2
// for 8 doubles) rather than a row of W, so its rays stay close together and
// part ways later in a BVH walk over small triangles -- and their colours go
// straight into the image. (A pixel's colour does not depend on its packet.)
template <typename T, typename S>
void render_centres(const S& shader, const CameraRays<T>& camera, int x0, int x1, int y0, int y1,
                    const PrimitiveSubset* visible, Image& image, RayCounts& counts) {
    constexpr int W = kLanes<T>;
    constexpr int BW = W < 4 ? W : 4, BH = W / BW;
    Lanes<T> dx, dy;
    for (int i = 0; i < W; ++i) dx[i] = T(i % BW), dy[i] = T(i / BW);
    struct Block {
        int x, y, nx, ny;
    };
    Block blocks[(kTileSize / BW + 1) * (kTileSize / BH + 1)];
    int n = 0;
    for (int y = y0; y < y1; y += BH)
        for (int x = x0; x < x1; x += BW) blocks[n++] = {x, y, std::min(BW, x1 - x), std::min(BH, y1 - y)};
    // Lanes past a block's edge repeat a pixel of it, inactive.
    auto rays_of = [&](const Block& b) FH_HOT_LAMBDA {
        const Lanes<T> px = min(T(b.x) + dx, splat(T(b.x + b.nx - 1))) + T(0.5);
        const Lanes<T> py = min(T(b.y) + dy, splat(T(b.y + b.ny - 1))) + T(0.5);
        return camera.generate(px, py);
    };
    RayPacket<T> rays = rays_of(blocks[0]);
    for (int k = 0; k < n; ++k) {
        const Block& b = blocks[k];
        // The next block's rays before this one is traced: their square root
        // and division (a long wait in double) run beside the trace.
        const RayPacket<T> next = k + 1 < n ? rays_of(blocks[k + 1]) : rays;
        const LaneInts<T> active = (dx < T(b.nx)) & (dy < T(b.ny));
        counts.primary += std::uint64_t(b.nx * b.ny);
        const ColorLanes<T> c = clamp_samples(shader.trace(rays, active, counts, visible), active, counts);
        const typename WideLanes<T>::Bytes bytes[3] = {to_bytes<T>(c.x), to_bytes<T>(c.y), to_bytes<T>(c.z)};
        if (b.nx == BW && b.ny == BH) {
            const auto rgb = interleave_rgb<W>(bytes, std::make_index_sequence<2 * W>{});
            const auto* row = reinterpret_cast<const std::uint8_t*>(&rgb);
            for (int j = 0; j < BH; ++j) std::memcpy(image.pixel(b.x, b.y + j), row + 3 * BW * j, 3 * BW);
        } else {  // a block cut by the tile's edge
            // As plain bytes: GCC 12 took the vectors' lanes read one at a
            // time for uninitialized (-Wmaybe-uninitialized).
            std::uint8_t plain[3][W];
            std::memcpy(plain, bytes, sizeof plain);
            for (int j = 0; j < b.ny; ++j) {
                std::uint8_t* out = image.pixel(b.x, b.y + j);
                for (int i = 0; i < b.nx; ++i)
                    for (int ch = 0; ch < 3; ++ch) out[3 * i + ch] = plain[ch][j * BW + i];
            }
        }
        rays = next;
    }
}

// spp samples in each pixel of a list (at most kTileSize^2 of them; a tile's
// or the adaptive pass's), a packet of samples at a time in pixel order; the
// pixel is the mean of its clamped samples, rounded. visible: what the
// samples' camera rays can hit (nullptr: anything).
template <typename T, typename S>
void render_pixels(const S& shader, const CameraRays<T>& camera, const PixelRef* pixels, int count,
                   int spp, const PrimitiveSubset* visible, Image& image, RayCounts& counts) {
    constexpr int W = kLanes<T>;
    if (count == 0) return;
    const StrataGrid grid = strata_for(spp);
    const int samples = count * spp;
    int pixel = 0, sample = 0;  // the next sample to take
    // The camera rays of the next packet's samples, every lane's cell at
    // once (past the last sample, the lanes repeat a pixel of the list,
    // inactive); then every lane's jitter at once (PixelSamples'
    // `jittered`, lane by lane).
    using Doubles = typename WideLanes<T>::Doubles;
    using Ints = typename WideLanes<T>::Ints;
    using Seeds = typename WideLanes<T>::Seeds;
    using Uints = typename WideLanes<T>::Uints;
    // (A vector made once: from a scalar, GCC built it in memory at every
    // packet and waited on the load.)
    const Doubles unit = Doubles{} + 1.0 / double(spp);
    const int log_spp = (spp & (spp - 1)) == 0 ? __builtin_ctz(unsigned(spp)) : -1;
    Uints lane;
    for (int i = 0; i < W; ++i) lane[i] = unsigned(i);
    using Keys = PixelKeys<Uints, Seeds>;
    // The keys of the packet's pixels (of a pixel of many packets: set at
    // its first; zeroed here, as GCC cannot tell they are set before use).
    Keys keys{};
    auto take = [&]() FH_HOT_LAMBDA {
        Doubles px, py, lx, ly;
        Seeds hx;
        Uints ux, uy, us, cx, cy;
        if (spp % W == 0) {  // one pixel's samples; its keys at its first packet
            ux = Uints{} + pixels[pixel].x, uy = Uints{} + pixels[pixel].y, us = unsigned(sample) + lane;
            if (sample == 0) keys = Keys(unsigned(pixels[pixel].x), unsigned(pixels[pixel].y));
            if ((sample += W) == spp) sample = 0, ++pixel;
        } else {  // lane i: the sample after lane i - 1's, of its pixel or the next
            alignas(64) std::uint32_t x[W], y[W], in_pixel[W];
            if (log_spp >= 0) {  // 2^log_spp samples: W / spp whole pixels, by shifts
                for (int i = 0; i < W; ++i) {
                    const PixelRef& p = pixels[std::min(pixel + ((sample + i) >> log_spp), count - 1)];
                    x[i] = p.x, y[i] = p.y;
                }
                us = (unsigned(sample) + lane) & unsigned(spp - 1);
                pixel += (sample + W) >> log_spp;
                sample = (sample + W) & (spp - 1);
            } else {
                for (int i = 0; i < W; ++i) {
                    const PixelRef& p = pixels[std::min(pixel, count - 1)];
                    x[i] = p.x, y[i] = p.y, in_pixel[i] = unsigned(sample);
                    if (++sample == spp) sample = 0, ++pixel;
                }
                std::memcpy(&us, in_pixel, sizeof us);
            }
            std::memcpy(&ux, x, sizeof ux);
            std::memcpy(&uy, y, sizeof uy);
            keys = Keys(ux, uy);
        }
        cells_at_once(grid, keys, us, cx, cy, hx);
        px = __builtin_convertvector(__builtin_convertvector(ux, Ints), Doubles);
        py = __builtin_convertvector(__builtin_convertvector(uy, Ints), Doubles);
        lx = __builtin_convertvector(__builtin_convertvector(cx, Ints), Doubles);
        ly = __builtin_convertvector(__builtin_convertvector(cy, Ints), Doubles);
        if (spp == 1) {  // the pixel's centre
            px += 0.5, py += 0.5;
        } else {
            mix64_in_place(hx);
            Seeds hy = hx;
            mix64_in_place(hy);
            // unit_from_bits: the top 24 bits, through 32-bit integers,
            // which every x86-64 level converts in one instruction.
            px += (lx + __builtin_convertvector(__builtin_convertvector(hx >> 40, Ints), Doubles) * 0x1p-24) * unit;
            py += (ly + __builtin_convertvector(__builtin_convertvector(hy >> 40, Ints), Doubles) * 0x1p-24) * unit;
        }
        return camera.generate(__builtin_convertvector(px, Lanes<T>), __builtin_convertvector(py, Lanes<T>));
    };
    // Each pixel's sum, sample by sample in their order, then its byte.
    double sum[3] = {0, 0, 0};
    int summed = 0, done = 0;  // samples in sum; pixels written
    RayPacket<T> rays = take();
    for (int first = 0; first < samples; first += W) {
        const int n = std::min(W, samples - first);
        // The next packet's rays before this one is traced: their square
        // root and division run beside the trace (as in render_centres).
        const RayPacket<T> next = first + W < samples ? take() : rays;
        const LaneInts<T> active = first_lanes<T>(n);
        counts.primary += std::uint64_t(n);
        const ColorLanes<T> c = clamp_samples(shader.trace(rays, active, counts, visible), active, counts);
        if (n == W && write_whole_pixels<T>(spp, c, pixels + done, image)) {  // (summed is 0)
            done += W / spp;
            rays = next;
            continue;
        }
        alignas(64) T rgb[3][W];
        store(rgb[0], c.x);
        store(rgb[1], c.y);
        store(rgb[2], c.z);
        for (int i = 0; i < n; ++i) {
            for (int k = 0; k < 3; ++k) sum[k] += double(rgb[k][i]);
            if (++summed == spp) {
                std::uint8_t* px = image.pixel(pixels[done].x, pixels[done].y);
                for (int k = 0; k < 3; ++k) px[k] = to_byte(sum[k] / double(spp)), sum[k] = 0;
                summed = 0;
                ++done;
            }
        }
        rays = next;
    }
}

// The pixels of tile t, in row order.
inline int tile_pixels(int t, int width, int height, PixelRef* out) {
    const int tiles_x = (width + kTileSize - 1) / kTileSize;
    const int x0 = (t % tiles_x) * kTileSize, y0 = (t / tiles_x) * kTileSize;
    int n = 0;
    for (int y = y0; y < std::min(y0 + kTileSize, height); ++y)
        for (int x = x0; x < std::min(x0 + kTileSize, width); ++x)
            out[n++] = {std::uint16_t(x), std::uint16_t(y)};
    return n;
}

}  // namespace detail

template <typename T>
FrameResult render_frame_as(const FlatScene<T>& flat, const Camera& camera, const RenderSettings& settings,
                            ThreadPool* pool) {
    using namespace detail;
    const auto start = std::chrono::steady_clock::now();
    const CameraRays<T> camera_rays(camera);
    FrameResult result;
    result.image = Image::unzeroed(camera.width, camera.height);
    result.plan = flat.plan;

    // What each worker writes: its ray counts and what its tile's camera
    // rays can hit (computed in double: render/tile_culling.h; rewritten
    // every tile, read for every packet). Cache lines apart, so that no line
    // goes back and forth between the cores.
    struct alignas(64) WorkerState {
        RayCounts counts;
        PrimitiveSubset visible;
    };
    const size_t workers = static_cast<size_t>(pool ? pool->size() : 1);
    std::vector<WorkerState> states(workers);
    const TileSides sides(CameraRays<double>(camera), camera.width, camera.height, kTileSize);
    auto run = [&](int tasks, const std::function<void(int, int)>& fn) {
        if (pool) pool->parallel_for(tasks, fn);
        else for (int t = 0; t < tasks; ++t) fn(t, 0);
    };
    constexpr int kChunk = kTileSize * kTileSize;
    with_shader(flat, [&](const auto& shader) {
        const int tiles = ((camera.width + kTileSize - 1) / kTileSize) *
                          ((camera.height + kTileSize - 1) / kTileSize);
        const int tiles_x = (camera.width + kTileSize - 1) / kTileSize;
        run(tiles, [&](int t, int worker) {
            RayCounts& c = states[size_t(worker)].counts;
            const int x0 = (t % tiles_x) * kTileSize, y0 = (t / tiles_x) * kTileSize;
            const int x1 = std::min(x0 + kTileSize, camera.width), y1 = std::min(y0 + kTileSize, camera.height);
            PrimitiveSubset& visible = states[size_t(worker)].visible;
            cull_to_frustum(*flat.geometry, sides.frustum(x0, x1, y0, y1), visible);
            if (settings.samples_per_pixel == 1) {
                render_centres<T>(shader, camera_rays, x0, x1, y0, y1, &visible, result.image, c);
                return;
            }
            PixelRef pixels[kChunk];
            const int n = tile_pixels(t, camera.width, camera.height, pixels);
            render_pixels<T>(shader, camera_rays, pixels, n, settings.samples_per_pixel, &visible,
                             result.image, c);
        });
        if (!settings.adaptive) return;
        const std::vector<PixelRef> refine =
            pixels_to_refine(result.image, settings.adaptive_threshold);
        result.refined_pixels = refine.size();
        const int chunks = int((refine.size() + kChunk - 1) / kChunk);
        // Each of a refined pixel's samples stands for its share of the pixel.
        const auto refining = shader.with_cone(PixelCone<T>::of(camera, settings.adaptive_samples));
        run(chunks, [&](int c, int worker) {
            const int n = std::min(kChunk, int(refine.size()) - c * kChunk);
            render_pixels<T>(refining, camera_rays, refine.data() + c * kChunk, n,
                             settings.adaptive_samples, nullptr, result.image, states[size_t(worker)].counts);
        });
    }, PixelCone<T>::of(camera, settings.samples_per_pixel));
    for (const WorkerState& w : states) result.counts += w.counts;
    result.render_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace fh
