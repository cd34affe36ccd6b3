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

// Bounding spheres of consecutive runs of the triangles the frame keeps,
// computed in double and padded by a relative 1e-4 so that no rounding in
// the tracer's precision can cull a ray that hits a triangle.
template <typename T>
std::vector<TriangleCluster<T>> clusters_of(const std::vector<const Triangle<double>*>& tris) {
    const int kept = int(tris.size());
    std::vector<TriangleCluster<T>> out;
    for (int first = 0; first < kept; first += kClusterSize) {
        const int count = std::min(kClusterSize, kept - first);
        dvec3 lo(kInfinity<double>), hi(-kInfinity<double>);
        auto corners = [&](const Triangle<double>& t, auto&& fn) {
            fn(t.v0);
            fn(t.v1);
            fn(t.v2);
        };
        for (int i = first; i < first + count; ++i)
            corners(*tris[size_t(i)], [&](const dvec3& p) {
                lo = glm::min(lo, p);
                hi = glm::max(hi, p);
            });
        const dvec3 center = (lo + hi) * 0.5;
        double r = 0;
        for (int i = first; i < first + count; ++i)
            corners(*tris[size_t(i)], [&](const dvec3& p) { r = std::max(r, glm::length(p - center)); });
        r = r * (1 + 1e-4) + 1e-4 * max_abs_component(center) + 1e-30;
        out.push_back({Vec3<T>(center), T(r * r), first, count});
    }
    return out;
}

}  // namespace

template <typename T>
FlatScene<T> FlatScene<T>::build(const Scene& scene, const EffectPlan& plan) {
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
    f.clusters = clusters_of<T>(kept);
    for (size_t i = 0; i < f.spheres.size(); ++i) f.everything.spheres.push_back(int(i));
    for (size_t i = 0; i < f.clusters.size(); ++i) f.everything.clusters.push_back(int(i));

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
