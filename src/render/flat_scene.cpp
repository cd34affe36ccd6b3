#include "render/flat_scene.h"

#include <algorithm>

namespace fh {

namespace {

template <typename T>
Material<T> cast(const Material<double>& m) {
    return {Color<T>(m.ambient_color), Color<T>(m.diffuse_color), Color<T>(m.specular_color),
            T(m.ambient), T(m.diffuse), T(m.specular), T(m.phong_exponent), m.glazed,
            T(m.reflectivity)};
}

template <typename T>
LightTerms<T> terms(const Material<double>& m, const dvec3& light_color, double intensity,
                    const Effects& fx) {
    LightTerms<T> t;
    if (fx.diffuse) t.diffuse = Color<T>(intensity * m.diffuse * light_color * m.diffuse_color);
    if (fx.specular) t.specular = Color<T>(intensity * m.specular * light_color * m.specular_color);
    return t;
}

}  // namespace

template <typename T>
FlatScene<T> FlatScene<T>::build(const Scene& scene, const Effects& effects, int max_depth) {
    FlatScene<T> f;
    for (const auto& s : scene.spheres)
        f.spheres.push_back({Vec3<T>(s.center), T(s.radius), s.material});
    for (const auto& p : scene.planes)
        f.planes.push_back({Vec3<T>(p.normal), T(p.distance), p.material});
    for (const auto& t : scene.triangles) {
        // A triangle without area can never be hit: leave it out of the loop.
        if (t.normal == dvec3(0)) continue;
        f.triangles.push_back({Vec3<T>(t.v0), Vec3<T>(t.e1), Vec3<T>(t.e2), Vec3<T>(t.normal),
                               t.material});
    }
    for (const auto& m : scene.materials) f.materials.push_back(cast<T>(m));

    // The plan: what can contribute to this frame.
    EffectPlan& plan = f.plan;
    plan.effects = effects;
    const bool any_glazed = std::any_of(scene.materials.begin(), scene.materials.end(),
                                        [](const auto& m) { return m.glazed; });
    plan.effects.glazing = effects.glazing && any_glazed && max_depth > 0;
    plan.max_depth = plan.effects.glazing ? max_depth : 0;

    const size_t nm = scene.materials.size();
    f.ambient_terms.assign(nm, Color<T>(0));
    bool any_ambient = false;
    for (const auto& a : scene.ambient_lights) {
        if (!effects.ambient || a.intensity == 0) continue;
        any_ambient = true;
        for (size_t m = 0; m < nm; ++m) {
            const auto& mat = scene.materials[m];
            f.ambient_terms[m] += Color<T>(a.intensity * mat.ambient * a.color * mat.ambient_color);
        }
    }
    plan.effects.ambient = any_ambient;

    const bool direct = effects.diffuse || effects.specular;
    for (const auto& l : scene.directional_lights) {
        if (!direct || l.intensity == 0) continue;
        f.directional_lights.push_back({l.name, Color<T>(l.color), T(l.intensity),
                                        Vec3<T>(l.direction)});
        for (const auto& mat : scene.materials)
            f.directional_terms.push_back(terms<T>(mat, l.color, l.intensity, effects));
    }
    for (const auto& l : scene.spot_lights) {
        if (!direct || l.intensity == 0) continue;
        f.spot_lights.push_back({l.name, Color<T>(l.color), T(l.intensity), Vec3<T>(l.position),
                                 Vec3<T>(l.axis), T(l.max_angle)});
        for (const auto& mat : scene.materials)
            f.spot_terms.push_back(terms<T>(mat, l.color, 1.0, effects));
    }
    const bool any_direct_light = !f.directional_lights.empty() || !f.spot_lights.empty();
    plan.effects.diffuse = effects.diffuse && any_direct_light;
    plan.effects.specular = effects.specular && any_direct_light;
    plan.effects.shadows = effects.shadows && any_direct_light;
    return f;
}

template struct FlatScene<float>;
template struct FlatScene<double>;

}  // namespace fh
