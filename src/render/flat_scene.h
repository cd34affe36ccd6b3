// The scene as the hot loop reads it: contiguous arrays per shape kind in the
// tracer's scalar type, only the lights that can contribute, and each light's
// colour products with each material computed once per frame instead of once
// per ray. Built from a Scene for one frame; no allocation after that.
#pragma once

#include <vector>

#include "core/hit.h"
#include "render/effect_plan.h"
#include "scene/scene.h"

namespace fh {

// intensity * strength * (light colour (.) material colour), for one light and
// one material; the spot light's falloff multiplies it per point.
template <typename T>
struct LightTerms {
    Color<T> diffuse{0};
    Color<T> specular{0};
};

// Up to kClusterSize consecutive triangles and a sphere that holds them all.
// A batch of rays none of which meets the sphere skips the triangles: a
// 16 x 16 tile mostly does not see the report's tetrahedron at all.
template <typename T>
struct TriangleCluster {
    Vec3<T> center;
    T radius2;  // padded so rounding never culls a real hit
    int first, count;

    // Where the ray leaves the bounding sphere, or infinity if it never meets
    // it ahead of its origin. A plain test is enough for a padded bound (the
    // robust one of Sphere costs more), and it is branch-free, so a loop of
    // it over a batch vectorises.
    FH_HOT_INLINE T exit_t(const Ray<T>& ray) const {
        const Vec3<T> f = ray.origin - center;
        const T b = -glm::dot(f, ray.direction);
        const Vec3<T> closest = f + b * ray.direction;
        const T disc = radius2 - glm::dot(closest, closest);
        const T far = b + std::sqrt(std::max(disc, T(0)));
        return ((disc >= T(0)) & (far > T(0))) ? far : kInfinity<T>;
    }
};
inline constexpr int kClusterSize = 16;

template <typename T>
struct FlatScene {
    std::vector<Sphere<T>> spheres;
    std::vector<Plane<T>> planes;
    std::vector<Triangle<T>> triangles;
    std::vector<TriangleCluster<T>> clusters;  // covering the triangles in order
    std::vector<Material<T>> materials;
    std::vector<Color<T>> ambient_terms;  // per material
    std::vector<DirectionalLight<T>> directional_lights;
    std::vector<SpotLight<T>> spot_lights;
    std::vector<LightTerms<T>> directional_terms;  // [light * materials + material]
    std::vector<LightTerms<T>> spot_terms;         // [light * materials + material]
    EffectPlan plan;

    // Only what the plan simulates: lights it uses, terms of its effects.
    static FlatScene build(const Scene& scene, const EffectPlan& plan);

    // The hit of a batch intersection: prim numbers spheres, then planes,
    // then triangles (render/batch_intersect.h).
    Hit<T> hit_of(T t, int prim) const {
        const int ns = int(spheres.size()), np = int(planes.size());
        if (prim < ns) return {t, ShapeKind::sphere, prim};
        if (prim < ns + np) return {t, ShapeKind::plane, prim - ns};
        return {t, ShapeKind::triangle, prim - ns - np};
    }

    // Point, normal facing the ray, and material of a hit.
    SurfacePoint<T> surface(const Ray<T>& ray, const Hit<T>& hit) const {
        SurfacePoint<T> sp;
        switch (hit.kind) {
        case ShapeKind::sphere: {
            const Sphere<T>& s = spheres[hit.index];
            sp.normal = s.normal_at(ray.at(hit.t));
            sp.point = s.center + s.radius * sp.normal;  // Sphere::point_at, normal kept
            sp.material = s.material;
            break;
        }
        case ShapeKind::plane: {
            const Plane<T>& p = planes[hit.index];
            sp.point = p.point_at(ray, hit.t);
            sp.normal = p.normal;
            sp.material = p.material;
            break;
        }
        case ShapeKind::triangle: {
            const Triangle<T>& tr = triangles[hit.index];
            sp.point = tr.point_at(ray, hit.t);
            sp.normal = tr.normal;
            sp.material = tr.material;
            break;
        }
        case ShapeKind::none:
            break;
        }
        if (glm::dot(sp.normal, ray.direction) > T(0)) sp.normal = -sp.normal;
        return sp;
    }
};

extern template struct FlatScene<float>;
extern template struct FlatScene<double>;

}  // namespace fh
