// Micro-benchmarks of the tracer's hot code (Google Benchmark): each shape's
// intersection on packets of rays that hit it (so no packet takes the
// early-out) and that miss it (so every packet does), the nearest hit of a
// tile's camera rays against the report's scene, and the shading of that
// tile. Frame-level timing is `firsthit bench`.
//   build/bench/firsthit_bench [--benchmark_filter=Sphere]
//   (after cmake --build build --target firsthit_bench: not in the default build)
#include <benchmark/benchmark.h>

#include <vector>

#include "yaml/scene_loader.h"
#include "render/render.h"
#include "render/shading.h"

namespace fh {
namespace {

const Scene& report_scene() {
    static const Scene s = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml").scene;
    return s;
}

constexpr int kTile = 16;  // the benchmarks' rays: one 16 x 16 tile, 256 of them

// A tile of the perspective view's camera rays, 16 x 16 pixels with its
// corner at (x0, y0), as packets.
template <typename T>
std::vector<RayPacket<T>> camera_tile(int x0, int y0) {
    const CameraRays<T> cam(*report_scene().find_camera("perspective"));
    std::vector<RayPacket<T>> out;
    constexpr int W = kLanes<T>;
    for (int first = 0; first < kTile * kTile; first += W) {
        alignas(64) T px[W], py[W];
        for (int i = 0; i < W; ++i) {
            px[i] = T(x0 + (first + i) % kTile) + T(0.5);
            py[i] = T(y0 + (first + i) / kTile) + T(0.5);
        }
        out.push_back(cam.generate(load(px), load(py)));
    }
    return out;
}

// Rays from (0, 0, 20) toward points spread over a disc of `spread` around
// target: with a spread below the shape's size, every ray hits it.
template <typename T>
std::vector<RayPacket<T>> rays_toward(const dvec3& target, double spread) {
    std::vector<RayPacket<T>> out;
    constexpr int W = kLanes<T>;
    const dvec3 eye(0, 0, 20);
    for (int first = 0; first < kTile * kTile; first += W) {
        RayPacket<T> p = RayPacket<T>::splat({Vec3<T>(eye), Vec3<T>(0, 0, -1)});
        for (int i = 0; i < W; ++i) {
            const int k = first + i;
            const dvec3 aim = target + spread * dvec3((k % kTile) / 15.0 - 0.5, (k / kTile) / 15.0 - 0.5, 0);
            const Vec3<T> d(glm::normalize(aim - eye));
            p.direction.x[i] = d.x;
            p.direction.y[i] = d.y;
            p.direction.z[i] = d.z;
        }
        out.push_back(p);
    }
    return out;
}

template <typename T, typename Intersect>
void intersect_packets(benchmark::State& state, const std::vector<RayPacket<T>>& rays,
                       Intersect intersect) {
    for (auto _ : state)
        for (const RayPacket<T>& p : rays) benchmark::DoNotOptimize(intersect(p));
    state.SetItemsProcessed(state.iterations() * kTile * kTile);
}

// The red sphere: r = 1 at (-3, 0, 0).
template <typename T>
void BM_Sphere(benchmark::State& state) {
    const Sphere<T> s{{-3, 0, 0}, 1, 0};
    const bool hit = state.range(0) != 0;
    const auto rays = rays_toward<T>(hit ? dvec3(-3, 0, 0) : dvec3(3, 0, 0), 1.2);
    intersect_packets<T>(state, rays, [&](const RayPacket<T>& p) {
        return s.intersect(p, T(0), splat(kInfinity<T>));
    });
}

template <typename T>
void BM_Plane(benchmark::State& state) {
    const Plane<T> floor{{0, 0, 1}, -1, 0};
    const auto rays = rays_toward<T>(dvec3(0, 0, -1), 10);
    intersect_packets<T>(state, rays, [&](const RayPacket<T>& p) {
        return floor.intersect(p, T(0), splat(kInfinity<T>));
    });
}

// The tetrahedron's base, (-5,5,0) (-7,5,0) (-6,7,0); the ray basis is built
// per packet, as the tracer does once for all triangles.
template <typename T>
void BM_Triangle(benchmark::State& state) {
    const auto tri = Triangle<T>::make({-5, 5, 0}, {-7, 5, 0}, {-6, 7, 0}, 0);
    const bool hit = state.range(0) != 0;
    const auto rays = rays_toward<T>(hit ? dvec3(-6, 5.8, 0) : dvec3(6, 5.8, 0), 0.8);
    intersect_packets<T>(state, rays, [&](const RayPacket<T>& p) {
        return tri.intersect(RayBasis<T>(p), T(0), splat(kInfinity<T>));
    });
}

// Nearest hits of a tile of camera rays against the whole scene (9
// primitives). Tile (384, 384) is the middle of the perspective view;
// (208, 416) is all tetrahedron.
template <typename T>
void BM_ClosestHits(benchmark::State& state) {
    const Scene& s = report_scene();
    const auto flat = FlatScene<T>::build(s, plan_effects(s, Effects{}, 5));
    const auto rays = camera_tile<T>(int(state.range(0)), int(state.range(1)));
    for (auto _ : state)
        for (const RayPacket<T>& p : rays)
            benchmark::DoNotOptimize(closest_hits(*flat.geometry, p, first_lanes<T>(kLanes<T>)));
    state.SetItemsProcessed(state.iterations() * kTile * kTile);
}

// Shading a tile of camera rays with every effect and all three lights
// (shadow rays, reflections up to depth 5).
template <typename T>
void BM_ShadeTile(benchmark::State& state) {
    const Scene& s = report_scene();
    const auto flat = FlatScene<T>::build(s, plan_effects(s, Effects{}, 5));
    const auto rays = camera_tile<T>(int(state.range(0)), int(state.range(1)));
    // The report's scene calls for every effect: its shader variant alone.
    // with_shader would instantiate all sixteen, which made this file the
    // longest compile of CI (four minutes on one core).
    constexpr unsigned kEvery = kShadows | kSpecular | kGlazing;
    if (shader_features(flat.plan) != kEvery || flat.instances) {
        state.SkipWithError("the report's scene no longer calls for every effect");
        return;
    }
    const Shader<T, kEvery> shader(flat);
    RayCounts counts;
    for (auto _ : state)
        for (const RayPacket<T>& p : rays)
            benchmark::DoNotOptimize(shader.trace(p, first_lanes<T>(kLanes<T>), counts));
    state.SetItemsProcessed(state.iterations() * kTile * kTile);
    // Camera rays plus the shadow and reflection rays they spawned.
    state.counters["rays_per_camera_ray"] =
        1 + double(counts.total()) / double(state.iterations() * kTile * kTile);
}

BENCHMARK(BM_Sphere<float>)->ArgName("hit")->Arg(1)->Arg(0);
BENCHMARK(BM_Sphere<double>)->ArgName("hit")->Arg(1)->Arg(0);
BENCHMARK(BM_Plane<float>);
BENCHMARK(BM_Plane<double>);
BENCHMARK(BM_Triangle<float>)->ArgName("hit")->Arg(1)->Arg(0);
BENCHMARK(BM_Triangle<double>)->ArgName("hit")->Arg(1)->Arg(0);
BENCHMARK(BM_ClosestHits<float>)->ArgNames({"x", "y"})->Args({384, 384})->Args({208, 416});
BENCHMARK(BM_ClosestHits<double>)->ArgNames({"x", "y"})->Args({384, 384})->Args({208, 416});
BENCHMARK(BM_ShadeTile<float>)->ArgNames({"x", "y"})->Args({384, 384})->Args({208, 416});
BENCHMARK(BM_ShadeTile<double>)->ArgNames({"x", "y"})->Args({384, 384})->Args({208, 416});

}  // namespace
}  // namespace fh

BENCHMARK_MAIN();
