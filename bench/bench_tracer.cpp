// Micro-benchmarks of the tracer's hot loops (Google Benchmark): each shape's
// intersection over a batch of rays, and the shading of one batch of camera
// rays of the report's scene. Frame-level timing is `firsthit bench`.
//   build/bench/firsthit_bench [--benchmark_filter=Sphere]
#include <benchmark/benchmark.h>

#include "io/scene_loader.h"
#include "render/render.h"
#include "render/shading.h"

namespace fh {
namespace {

const Scene& report_scene() {
    static const Scene s = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml");
    return s;
}

// A full batch of camera rays from the middle of the perspective view, in
// rows of 16 pixels.
template <typename T>
RayBatch<T> camera_batch() {
    const CameraRays<T> cam(*report_scene().find_camera("perspective"));
    RayBatch<T> b;
    for (int i = 0; i < RayBatch<T>::kCapacity; ++i)
        b.push(cam.generate(T(392 + i % 16), T(392 + i / 16)));
    return b;
}

template <typename T, typename Shape>
void intersect_batch(benchmark::State& state, const Shape& shape) {
    const RayBatch<T> rays = camera_batch<T>();
    T t[RayBatch<T>::kCapacity];
    for (auto _ : state) {
        for (int i = 0; i < rays.size; ++i) t[i] = shape.intersect(rays.ray(i), T(0), kInfinity<T>);
        benchmark::DoNotOptimize(t);
    }
    state.SetItemsProcessed(state.iterations() * rays.size);
}

template <typename T>
void BM_Sphere(benchmark::State& s) {
    intersect_batch<T>(s, Sphere<T>{{6, 6, 4}, 5, 0});
}
template <typename T>
void BM_Plane(benchmark::State& s) {
    intersect_batch<T>(s, Plane<T>{{0, 0, 1}, -1, 0});
}
template <typename T>
void BM_Triangle(benchmark::State& s) {
    intersect_batch<T>(s, Triangle<T>::make({-5, 5, 0}, {-7, 5, 0}, {-6, 6, 5}, 0));
}

// Nearest hits of a batch against the whole scene (9 primitives).
template <typename T>
void BM_ClosestHits(benchmark::State& state) {
    const Scene& s = report_scene();
    const auto flat = FlatScene<T>::build(s, plan_effects(s, s.effects, 5));
    const RayBatch<T> rays = camera_batch<T>();
    T t[RayBatch<T>::kCapacity];
    std::int32_t prim[RayBatch<T>::kCapacity];
    for (auto _ : state) {
        closest_hits(flat, rays, t, prim);
        benchmark::DoNotOptimize(t);
    }
    state.SetItemsProcessed(state.iterations() * rays.size);
}

// Shading one batch of camera rays with every effect (shadows, reflections).
template <typename T>
void BM_ShadeBatch(benchmark::State& state) {
    const Scene& s = report_scene();
    const auto flat = FlatScene<T>::build(s, plan_effects(s, s.effects, 5));
    const RayBatch<T> camera = camera_batch<T>();
    RayBatch<T> rays;
    Color<T> colours[RayBatch<T>::kCapacity];
    RayCounts counts;
    with_shader(flat, [&](const auto& shader) {
        for (auto _ : state) {
            rays = camera;
            shader.trace(rays, colours, counts);
            benchmark::DoNotOptimize(colours);
        }
    });
    state.SetItemsProcessed(state.iterations() * camera.size);
    // Camera rays plus the shadow and reflection rays they spawned.
    state.counters["rays_per_camera_ray"] =
        1 + double(counts.total()) / double(state.iterations() * camera.size);
}

BENCHMARK(BM_Sphere<float>);
BENCHMARK(BM_Sphere<double>);
BENCHMARK(BM_Plane<float>);
BENCHMARK(BM_Plane<double>);
BENCHMARK(BM_Triangle<float>);
BENCHMARK(BM_Triangle<double>);
BENCHMARK(BM_ClosestHits<float>);
BENCHMARK(BM_ClosestHits<double>);
BENCHMARK(BM_ShadeBatch<float>);
BENCHMARK(BM_ShadeBatch<double>);

}  // namespace
}  // namespace fh

BENCHMARK_MAIN();
