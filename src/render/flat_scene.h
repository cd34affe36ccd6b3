// The scene as the tracer reads it: contiguous arrays per shape kind in the
// tracer's scalar type, only the lights that can contribute, and each light's
// colour products with each material computed once per frame instead of once
// per ray. Built from a Scene for one frame; tracing allocates nothing.
#pragma once

#include <vector>

#include "core/hit.h"
#include "render/bvh_traversal.h"
#include "render/effect_plan.h"
#include "scene/scene.h"

namespace fh {

// The bounded primitives a tile's camera rays can hit (render/tile_culling.h),
// as indices into the BVH's input (spheres, then triangles), in increasing
// order. A short list is tested one by one, which for a few primitives is
// faster than walking the BVH; past kMaxSubset the walk is used instead.
struct PrimitiveSubset {
    std::vector<int> prims;
    bool walk_bvh = true;  // too many (or not culled): walk the BVH
};
inline constexpr size_t kMaxSubset = 16;

// Primitive ids number the spheres, then the planes, then the (kept) triangles.
inline constexpr int kNoHit = -1;

// A padded sphere around all of a small scene's triangles (FlatScene::
// few_triangles). A ray that misses it skips them all, with no division and
// no walk: for a scene of a few primitives -- the report's has seven --
// that is faster than any BVH.
template <typename T>
struct BoundingSphere {
    Vec3<T> center{0};
    T radius2 = 0;  // padded so rounding never culls a real hit

    // Per lane: the ray meets the sphere ahead of its origin (or starts
    // inside it). A plain test is enough for a padded bound; the robust one
    // of Sphere costs more. The far root b + sqrt(disc) is ahead when b > 0
    // or disc > b^2, which needs no square root.
    FH_HOT_INLINE LaneInts<T> reaches(const RayPacket<T>& ray) const {
        const Vec3Lanes<T> f = ray.origin - center;
        const Lanes<T> b = -dot(f, ray.direction);
        const Vec3Lanes<T> closest = f + b * ray.direction;
        const Lanes<T> disc = radius2 - dot(closest, closest);
        return (disc >= T(0)) & ((b > T(0)) | (disc > b * b));
    }
};

// Where a primitive's surface is: what shading needs to turn a hit into a
// point and a normal.
template <typename T>
struct PrimitiveSurface {
    bool sphere = false;  // else flat: a plane or a triangle
    Vec3<T> anchor{0};    // sphere: the centre; flat: a point on it
    Vec3<T> normal{0};    // flat: the unit normal
    T radius = 0;         // sphere
    int material = -1;

    // For points p on the surface (up to the rounding of a ray's travel): p
    // projected back onto it -- its error is then a few ulps of its own
    // coordinates, not of the ray's travel -- and the unit normal there
    // (facing outward, not yet the ray).
    FH_HOT_INLINE void project(const Vec3Lanes<T>& p, Vec3Lanes<T>& point,
                               Vec3Lanes<T>& unit_normal) const {
        if (sphere) {
            unit_normal = normalize(p - anchor);
            point = anchor + radius * unit_normal;
        } else {
            unit_normal = Vec3Lanes<T>::splat(normal);
            point = p - dot(normal, p - anchor) * normal;
        }
    }

    // One point (tests): the same formula with p in every lane.
    void project(const Vec3<T>& p, Vec3<T>& point, Vec3<T>& unit_normal) const {
        Vec3Lanes<T> q, n;
        project(Vec3Lanes<T>::splat(p), q, n);
        point = q.lane(0);
        unit_normal = n.lane(0);
    }
};

template <typename T>
PrimitiveSurface<T> surface_of(const Sphere<T>& s) {
    return {true, s.center, Vec3<T>(0), s.radius, s.material};
}
template <typename T>
PrimitiveSurface<T> surface_of(const Plane<T>& p) {
    return {false, p.distance * p.normal, p.normal, T(0), p.material};
}
template <typename T>
PrimitiveSurface<T> surface_of(const Triangle<T>& t) {
    return {false, t.v0, t.normal, T(0), t.material};
}

// What shading reads about a material, in the tracer's type.
template <typename T>
struct MaterialShading {
    Color<T> ambient{0};  // the ambient term, summed over the ambient lights
    bool glazed = false;  // a hit sends a reflection ray
    T reflectivity = 0;
    T exponent = 0;       // Phong
    bool whole_exponent = true;  // the exponent is whole and at most kWholePowerLimit
};

// intensity * strength * (light colour (.) material colour), for one light and
// one material; the spot light's falloff multiplies it per point.
template <typename T>
struct LightTerms {
    Color<T> diffuse{0};
    Color<T> specular{0};
};

template <typename T>
struct FlatScene {
    std::vector<Sphere<T>> spheres;
    std::vector<Plane<T>> planes;
    std::vector<Triangle<T>> triangles;
    // Over the spheres and triangles: index i < spheres.size() is sphere i,
    // any other is triangle i - spheres.size().
    Bvh bvh;
    std::vector<NodeBox<T>> bvh_boxes;  // bvh.nodes' boxes in T
    // At most kMaxSubset spheres and triangles: no BVH walk, every sphere
    // tested, the triangles behind one bounding sphere, all in id order.
    bool small = false;
    BoundingSphere<T> few_triangles;
    // A small scene's every sphere and triangle, as a list in id order
    // (render/packet_intersect.h tests it one by one); larger: walk_bvh.
    PrimitiveSubset everything;
    std::vector<PrimitiveSurface<T>> surfaces;  // by primitive id
    std::vector<MaterialShading<T>> shading;    // by material
    std::vector<DirectionalLight<T>> directional_lights;
    std::vector<SpotLight<T>> spot_lights;
    std::vector<T> spot_widest_angles;  // by spot light: SpotLight::radiance_at's widest_angle
    // Each light's colour products with each material: [light * shading.size() + material].
    std::vector<LightTerms<T>> directional_terms;
    std::vector<LightTerms<T>> spot_terms;
    bool fractional_exponents = false;  // some material has whole == false: std::pow needed
    int exponent_bits = 0;              // bits of the largest whole exponent
    EffectPlan plan;

    // Only what the plan simulates: lights it uses, terms of its effects.
    // pool: the BVH is built on it (nullptr: on the calling thread).
    static FlatScene build(const Scene& scene, const EffectPlan& plan, ThreadPool* pool = nullptr);

    Hit<T> hit_of(T t, int prim) const {
        const int ns = int(spheres.size()), np = int(planes.size());
        if (prim < ns) return {t, ShapeKind::sphere, prim};
        if (prim < ns + np) return {t, ShapeKind::plane, prim - ns};
        return {t, ShapeKind::triangle, prim - ns - np};
    }

    // Point, normal facing the ray, and material of one hit (tests): the
    // formula shading uses, on a packet of one.
    SurfacePoint<T> surface(const Ray<T>& ray, const Hit<T>& hit) const {
        const int ns = int(spheres.size()), np = int(planes.size());
        int prim = hit.index;
        if (hit.kind == ShapeKind::plane) prim += ns;
        if (hit.kind == ShapeKind::triangle) prim += ns + np;
        const PrimitiveSurface<T>& s = surfaces[size_t(prim)];
        const RayPacket<T> packet = RayPacket<T>::splat(ray);
        Vec3Lanes<T> point, normal;
        s.project(packet.at(splat(hit.t)), point, normal);
        normal = facing(normal, packet.direction);
        return {point.lane(0), normal.lane(0), s.material};
    }

    // The normal turned to face the ray (report 8.4).
    static FH_HOT_INLINE Vec3Lanes<T> facing(const Vec3Lanes<T>& normal,
                                             const Vec3Lanes<T>& direction) {
        return select(dot(normal, direction) > T(0), -normal, normal);
    }
};

extern template struct FlatScene<float>;
extern template struct FlatScene<double>;

}  // namespace fh
