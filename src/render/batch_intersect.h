// Intersecting a batch of rays with the flat scene: for each primitive, one
// branch-free loop over the rays. The loop bodies are the shapes' own
// intersect functions (geometry/), so there is one copy of each formula.
#pragma once

#include <cstdint>
#include <type_traits>

#include "render/flat_scene.h"
#include "core/ray_batch.h"

namespace fh {

// Shadow-ray results: 0 (clear) or 1 (blocked), as wide as T.
template <typename T>
using BlockMask = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;

// Primitive ids: spheres first, then planes, then triangles (FlatScene::surface_of).
inline constexpr std::int32_t kNoHit = -1;

namespace detail {
template <typename T, typename Shape>
void nearest_of(const Shape& shape, std::int32_t id, const RayBatch<T>& rays, T* __restrict t,
                std::int32_t* __restrict prim) {
    for (int i = 0; i < rays.size; ++i) {
        const T ti = shape.intersect(rays.ray(i), T(0), t[i]);
        prim[i] = ti < t[i] ? id : prim[i];
        t[i] = ti < t[i] ? ti : t[i];
    }
}

// blocked is an integer as wide as T, so the loop vectorises with one lane per ray.
template <typename T, typename Shape>
void blocks(const Shape& shape, const RayBatch<T>& rays, BlockMask<T>* __restrict blocked) {
    for (int i = 0; i < rays.size; ++i) {
        const T t = shape.intersect(rays.ray(i), T(0), rays.t_max[i]);
        blocked[i] = t < rays.t_max[i] ? BlockMask<T>(1) : blocked[i];
    }
}
// Is reach(ray) >= 0 for any ray of the batch? An OR over the whole batch
// rather than a search that stops early: it vectorises like any other shape
// loop. It lets a whole batch skip a shape no ray of it can hit: a 16 x 16
// tile mostly sees one or two of the report's spheres and not the
// tetrahedron at all.
template <typename T, typename Reach>
bool any_reaches(const RayBatch<T>& rays, const Reach& reach) {
    BlockMask<T> any = 0;
    for (int i = 0; i < rays.size; ++i) any |= reach(rays.ray(i)) >= T(0) ? 1 : 0;
    return any != 0;
}

template <typename T>
bool any_reaches(const Sphere<T>& s, const RayBatch<T>& rays) {
    return any_reaches(rays, [&s](const Ray<T>& ray) FH_HOT_LAMBDA { return s.discriminant(ray); });
}

template <typename T>
bool any_reaches(const TriangleCluster<T>& c, const RayBatch<T>& rays) {
    return any_reaches(rays, [&c](const Ray<T>& ray) FH_HOT_LAMBDA { return c.reach(ray); });
}
}  // namespace detail

// t[i], prim[i]: the nearest hit of ray i with t > 0, or (infinity, kNoHit).
template <typename T>
void closest_hits(const FlatScene<T>& scene, const RayBatch<T>& rays, T* t, std::int32_t* prim) {
    for (int i = 0; i < rays.size; ++i) {
        t[i] = kInfinity<T>;
        prim[i] = kNoHit;
    }
    std::int32_t id = 0;
    for (const auto& s : scene.spheres) {
        if (detail::any_reaches(s, rays)) detail::nearest_of(s, id, rays, t, prim);
        ++id;
    }
    for (const auto& p : scene.planes) detail::nearest_of(p, id++, rays, t, prim);
    for (const auto& c : scene.clusters) {
        if (!detail::any_reaches(c, rays)) continue;
        for (int k = c.first; k < c.first + c.count; ++k)
            detail::nearest_of(scene.triangles[size_t(k)], id + k, rays, t, prim);
    }
}

// The nearest hit of one ray (tests, the viewer): a batch of one, so the same
// loops as every other ray.
template <typename T>
Hit<T> closest_hit(const FlatScene<T>& scene, const Ray<T>& ray) {
    RayBatch<T> one;
    one.push(ray);
    T t;
    std::int32_t prim;
    closest_hits(scene, one, &t, &prim);
    return prim == kNoHit ? Hit<T>{} : scene.hit_of(t, prim);
}

// blocked[i]: some surface lies in (0, t_max[i]) along ray i.
template <typename T>
void find_blocked(const FlatScene<T>& scene, const RayBatch<T>& rays, BlockMask<T>* blocked) {
    for (int i = 0; i < rays.size; ++i) blocked[i] = 0;
    for (const auto& s : scene.spheres)
        if (detail::any_reaches(s, rays)) detail::blocks(s, rays, blocked);
    for (const auto& p : scene.planes) detail::blocks(p, rays, blocked);
    for (const auto& c : scene.clusters) {
        if (!detail::any_reaches(c, rays)) continue;
        for (int k = c.first; k < c.first + c.count; ++k)
            detail::blocks(scene.triangles[size_t(k)], rays, blocked);
    }
}

}  // namespace fh
