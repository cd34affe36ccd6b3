#include "render/flat_scene.h"

#include <algorithm>
#include <bit>

namespace fh {

namespace {

template <typename T>
LightTerms<T> terms(const Material<double>& m, const dvec3& light_color, double intensity,
                    const Effects& fx) {
    LightTerms<T> t;
    if (fx.diffuse) t.diffuse = Color<T>(intensity * m.diffuse * light_color * m.diffuse_color);
    if (fx.specular) t.specular = Color<T>(intensity * m.specular * light_color * m.specular_color);
    return t;
}

// The boxes of the spheres, then of the triangles, computed in double and
// padded by a relative 1e-5 so that no rounding in the tracer's precision
// can put a hit outside its box.
Aabb padded(Aabb b) {
    const double pad = 1e-5 * (glm::length(b.hi - b.lo) + std::max(glm::length(b.lo), glm::length(b.hi)));
    b.lo -= pad;
    b.hi += pad;
    return b;
}
std::vector<Aabb> bounds_of(const std::vector<Sphere<double>>& spheres,
                            const std::vector<const Triangle<double>*>& triangles) {
    std::vector<Aabb> boxes;
    boxes.reserve(spheres.size() + triangles.size());
    for (const auto& s : spheres) boxes.push_back(padded({s.center - s.radius, s.center + s.radius}));
    for (const Triangle<double>* t : triangles) {
        Aabb b;
        b.grow(t->v0);
        b.grow(t->v1);
        b.grow(t->v2);
        boxes.push_back(padded(b));
    }
    return boxes;
}

// The padded bounding sphere of a few triangles.
template <typename T>
BoundingSphere<T> bounding_sphere(const std::vector<const Triangle<double>*>& triangles) {
    Aabb box;
    for (const Triangle<double>* t : triangles) {
        box.grow(t->v0);
        box.grow(t->v1);
        box.grow(t->v2);
    }
    if (box.empty()) return {};
    const dvec3 center = box.center();
    double r = 0;
    for (const Triangle<double>* t : triangles)
        for (const dvec3& p : {t->v0, t->v1, t->v2}) r = std::max(r, glm::length(p - center));
    r = r * (1 + 1e-4) + 1e-4 * max_abs_component(center) + 1e-30;
    return {Vec3<T>(center), T(r * r)};
}

// The triangles (and their surfaces) renumbered in the order the BVH's
// leaves list them, so a leaf's triangles lie next to each other in memory:
// a walk reads them in runs instead of from anywhere in a million. (Small
// scenes keep the file's order.)
template <typename T>
void in_leaf_order(FlatScene<T>& f) {
    const int ns = int(f.spheres.size()), np = int(f.planes.size());
    std::vector<Triangle<T>> triangles;
    std::vector<PrimitiveSurface<T>> surfaces(f.surfaces.begin(), f.surfaces.begin() + ns + np);
    triangles.reserve(f.triangles.size());
    for (std::int32_t& i : f.bvh.prims) {
        if (i < ns) continue;
        triangles.push_back(f.triangles[size_t(i - ns)]);
        surfaces.push_back(f.surfaces[size_t(np + i)]);
        i = ns + std::int32_t(triangles.size()) - 1;
    }
    f.triangles.swap(triangles);
    f.surfaces.swap(surfaces);
}

}  // namespace

template <typename T>
FlatScene<T> FlatScene<T>::build(const Scene& scene, const EffectPlan& plan, ThreadPool* pool) {
    FlatScene<T> f;
    f.plan = plan;
    const Effects& fx = plan.effects;

    // The ambient term of each material, summed over the ambient lights.
    // A light that is off but simulated anyway (plan not pruned) shines with 0.
    auto intensity = [](const auto& l) { return l.on ? l.intensity : 0.0; };
    std::vector<dvec3> ambient(scene.materials.size(), dvec3(0));
    for (const auto& a : scene.ambient_lights) {
        if (!fx.ambient || !plan.uses(a)) continue;
        for (size_t m = 0; m < ambient.size(); ++m) {
            const auto& mat = scene.materials[m];
            ambient[m] += intensity(a) * mat.ambient * a.color * mat.ambient_color;
        }
    }
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        const Material<double>& mat = scene.materials[m];
        const int whole = whole_exponent(mat.phong_exponent);
        f.shading.push_back({Color<T>(ambient[m]), mat.glazed, T(mat.reflectivity), T(mat.phong_exponent),
                             whole >= 0});
        f.fractional_exponents |= whole < 0 && fx.specular;
        if (whole > 0) f.exponent_bits = std::max(f.exponent_bits, int(std::bit_width(unsigned(whole))));
    }

    // Shapes and their surfaces, in primitive id order.
    for (const auto& s : scene.spheres) {
        f.spheres.push_back({Vec3<T>(s.center), T(s.radius), s.material});
        f.surfaces.push_back(surface_of(f.spheres.back()));
    }
    for (const auto& p : scene.planes) {
        f.planes.push_back({Vec3<T>(p.normal), T(p.distance), p.material});
        f.surfaces.push_back(surface_of(f.planes.back()));
    }
    std::vector<const Triangle<double>*> kept;
    for (const auto& t : scene.triangles) {
        // A triangle without area can never be hit: leave it out of the loop.
        if (t.degenerate()) continue;
        kept.push_back(&t);
        f.triangles.push_back({Vec3<T>(t.v0), Vec3<T>(t.v1), Vec3<T>(t.v2), Vec3<T>(t.normal),
                               t.material});
        f.surfaces.push_back(surface_of(f.triangles.back()));
    }
    const std::vector<Aabb> boxes = bounds_of(scene.spheres, kept);
    f.bvh = build_bvh(boxes, pool);
    f.bvh_boxes = boxes_of<T>(f.bvh);
    f.small = f.bvh.prims.size() <= kMaxSubset;
    if (f.small) {
        f.few_triangles = bounding_sphere<T>(kept);
        f.everything.walk_bvh = false;
        f.everything.prims.assign(f.bvh.prims.begin(), f.bvh.prims.end());
        std::sort(f.everything.prims.begin(), f.everything.prims.end());
    } else {
        in_leaf_order(f);
    }

    if (!fx.diffuse && !fx.specular) return f;
    // One row of colour products per light, by material.
    auto add_terms = [&](std::vector<LightTerms<T>>& out, const dvec3& color, double strength) {
        for (const auto& m : scene.materials) out.push_back(terms<T>(m, color, strength, fx));
    };
    for (const auto& l : scene.directional_lights) {
        if (!plan.uses(l)) continue;
        f.directional_lights.push_back({l.name, Color<T>(l.color), T(intensity(l)),
                                        Vec3<T>(l.direction)});
        add_terms(f.directional_terms, l.color, intensity(l));
    }
    for (const auto& l : scene.spot_lights) {
        if (!plan.uses(l)) continue;
        // The falloff keeps the real intensity; an off light (simulated only
        // when not pruning) gets zero colour terms instead, so its shadow rays
        // are still traced.
        f.spot_lights.push_back({l.name, Color<T>(l.color), T(l.intensity), Vec3<T>(l.position),
                                 Vec3<T>(l.axis), T(l.max_angle)});
        // theta never exceeds pi, so a cone that wide needs no test.
        const bool cone_test = !plan.pruned || l.max_angle < 3.14159265358979323846;
        f.spot_widest_angles.push_back(cone_test ? T(l.max_angle) : kInfinity<T>);
        add_terms(f.spot_terms, l.color, l.on ? 1.0 : 0.0);  // x falloff
    }
    return f;
}

template struct FlatScene<float>;
template struct FlatScene<double>;

}  // namespace fh
