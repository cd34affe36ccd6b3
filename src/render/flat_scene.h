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

// Three plain T. The shading loops fetch table rows by a per-ray index; GCC
// vectorises that (one load per lane) for plain fields, not through glm's
// vectors, whose components are unions.
template <typename T>
struct Plain3 {
    T x = 0, y = 0, z = 0;
    Plain3() = default;
    Plain3(const Vec3<T>& v) : x(v.x), y(v.y), z(v.z) {}  // NOLINT: implicit on purpose
    Vec3<T> vec() const { return {x, y, z}; }
};

// intensity * strength * (light colour (.) material colour), for one light and
// one material; the spot light's falloff multiplies it per point.
template <typename T>
struct LightTerms {
    Plain3<T> diffuse;
    Plain3<T> specular;
};

// Up to kClusterSize consecutive triangles and a sphere that holds them all.
// A batch of rays none of which meets the sphere skips the triangles: a
// 16 x 16 tile mostly does not see the report's tetrahedron at all.
template <typename T>
struct TriangleCluster {
    Vec3<T> center;
    T radius2;  // padded so rounding never culls a real hit
    int first, count;

    // >= 0 iff the ray meets the bounding sphere ahead of its origin (or
    // starts inside it). A plain test is enough for a padded bound (the
    // robust one of Sphere costs more), and it is branch-free, so a loop of
    // it over a batch vectorises.
    FH_HOT_INLINE T reach(const Ray<T>& ray) const {
        const Vec3<T> f = ray.origin - center;
        const T b = -glm::dot(f, ray.direction);
        const Vec3<T> closest = f + b * ray.direction;
        const T disc = radius2 - glm::dot(closest, closest);
        const T far = b + std::sqrt(std::max(disc, T(0)));
        return ((disc >= T(0)) & (far > T(0))) ? T(1) : T(-1);
    }
};
inline constexpr int kClusterSize = 16;

// What shading reads about the primitive a ray hit: one row per primitive id
// + 1 (row 0: no hit), so a batch loop fetches it with one index per ray.
// Every field is a T, so the fetch vectorises with the arithmetic around it.
template <typename T>
struct PrimitiveRow {
    Plain3<T> anchor;         // sphere: the centre; plane, triangle: a point on it
    Plain3<T> normal;         // plane, triangle: the unit normal
    T radius = 0;             // sphere
    T sphere = 0;             // 1 for a sphere
    Plain3<T> ambient;        // the material's ambient term, all ambient lights
    T glazed = 0;             // 1: a hit sends a reflection ray
    T reflectivity = 0;
    T exponent = 0;           // Phong
    T whole = 1;              // 1: exponent is whole and at most kWholePowerLimit
    int material = -1;
};

// Where a ray meets the primitive of a row at t: the point projected back
// onto the surface (its error is then a few ulps of its own coordinates, not
// of the ray's travel) and the unit normal facing the ray (report 8.4).
// Branch-free, for the shading loops; used for every hit, so one formula.
template <typename T>
FH_HOT_INLINE SurfacePoint<T> surface_at(const PrimitiveRow<T>& row, const Ray<T>& ray, T t) {
    const Vec3<T> anchor = row.anchor.vec(), normal = row.normal.vec();
    const Vec3<T> p = ray.at(t);
    const Vec3<T> q = p - anchor;
    const bool sphere = row.sphere != T(0);
    const Vec3<T> radial = glm::normalize(q);  // Sphere::normal_at
    const Vec3<T> on_sphere = anchor + row.radius * radial;
    const Vec3<T> on_plane = p - glm::dot(normal, q) * normal;
    // Selects per component: a select of whole vectors is a branch to GCC.
    auto pick = [sphere](const Vec3<T>& a, const Vec3<T>& b) {
        return Vec3<T>(sphere ? a.x : b.x, sphere ? a.y : b.y, sphere ? a.z : b.z);
    };
    SurfacePoint<T> sp;
    sp.normal = pick(radial, normal);
    sp.point = pick(on_sphere, on_plane);
    const T facing = glm::dot(sp.normal, ray.direction) > T(0) ? T(-1) : T(1);
    sp.normal *= facing;
    return sp;
}

template <typename T>
struct FlatScene {
    std::vector<Sphere<T>> spheres;
    std::vector<Plane<T>> planes;
    std::vector<Triangle<T>> triangles;
    std::vector<TriangleCluster<T>> clusters;  // covering the triangles in order
    std::vector<Material<T>> materials;
    std::vector<PrimitiveRow<T>> rows;  // [1 + primitive id]; rows[0]: no hit
    std::vector<DirectionalLight<T>> directional_lights;
    std::vector<SpotLight<T>> spot_lights;
    // Each light's colour products with each primitive's material:
    // [light * rows.size() + row].
    std::vector<LightTerms<T>> directional_terms;
    std::vector<LightTerms<T>> spot_terms;
    bool fractional_exponents = false;  // some row has whole == 0: std::pow needed
    int exponent_bits = 0;              // bits of the largest whole exponent
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
        const int ns = int(spheres.size()), np = int(planes.size());
        int prim = hit.index;
        if (hit.kind == ShapeKind::plane) prim += ns;
        if (hit.kind == ShapeKind::triangle) prim += ns + np;
        const PrimitiveRow<T>& row = rows[size_t(prim + 1)];
        SurfacePoint<T> sp = surface_at(row, ray, hit.t);
        sp.material = row.material;
        return sp;
    }
};

extern template struct FlatScene<float>;
extern template struct FlatScene<double>;

}  // namespace fh
