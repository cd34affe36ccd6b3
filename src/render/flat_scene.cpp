#include "render/flat_scene.h"

#include <algorithm>
#include <bit>
#include <memory>

namespace fh {

namespace {

template <typename T>
LightTerms<T> terms(const Material<double>& m, const dvec3& light_color, double intensity,
                    const Effects& fx) {
    LightTerms<T> t;
    if (fx.diffuse) t.diffuse = Color<T>(intensity * m.diffuse * light_color * m.diffuse_color);
    if (fx.specular) t.specular = Color<T>(intensity * m.specular * light_color * m.specular_color);
    if (m.metal_rough_texture >= 0) {
        if (fx.diffuse) t.diffuse_unit = Color<T>(intensity * light_color * m.diffuse_color);
        if (fx.specular) {
            t.tinted = Color<T>(intensity * light_color * m.diffuse_color);
            t.white = Color<T>(intensity * light_color * 255.0);
        }
    }
    return t;
}

}  // namespace

template <typename T>
FlatScene<T> FlatScene<T>::build(const Scene& scene, const EffectPlan& plan, ThreadPool* pool) {
    return build(scene, plan, std::make_shared<const FlatGeometry<T>>(FlatGeometry<T>::build(scene, pool)),
                 InstanceSet<T>::build(scene, pool));
}

template <typename T>
FlatScene<T> FlatScene<T>::build(const Scene& scene, const EffectPlan& plan,
                                 std::shared_ptr<const FlatGeometry<T>> geometry,
                                 std::shared_ptr<const InstanceSet<T>> instances) {
    FlatScene<T> f;
    f.geometry = std::move(geometry);
    f.instances = std::move(instances);
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
    // Materials on meshes with vertex colours are shaded as textured ones:
    // the colours multiply ambient and diffuse, not emissive.
    std::vector<bool> coloured(scene.materials.size(), false);
    for (const Instance& i : scene.instances) {
        if (!scene.meshes[size_t(i.mesh)].mesh->colors.empty()) coloured[size_t(i.material)] = true;
        f.blended |= scene.materials[size_t(i.material)].blend;
    }
    for (size_t m = 0; m < scene.materials.size(); ++m) {
        const Material<double>& mat = scene.materials[m];
        // An emissive texture shows lit or not; a turned normal and a
        // metallic-roughness texture only in the lights' terms and the
        // mirrored ray -- and a metal's texture may make a mirror of any hit.
        const bool may_mirror = mat.may_mirror() && plan.max_depth > 0;
        const bool bumpy = mat.normal_texture >= 0 && (fx.diffuse || fx.specular || may_mirror);
        const bool metal_rough = mat.metal_rough_texture >= 0 && (fx.diffuse || fx.specular || may_mirror);
        const bool textured =
            ((mat.texture >= 0 || mat.occlusion_texture >= 0 || coloured[m]) && (fx.ambient || fx.diffuse)) ||
            mat.emissive_texture >= 0 || bumpy || metal_rough;
        const dvec3 term = ambient[m];
        // (Added only when there is some: bytes as before for the report's.)
        if (mat.emissive != dvec3(0)) ambient[m] += mat.emissive;
        const int whole = whole_exponent(mat.phong_exponent);
        f.shading.push_back({Color<T>(ambient[m]), mat.glazed, T(mat.reflectivity), T(mat.phong_exponent),
                             whole >= 0, textured ? mat.texture : -1, textured ? Color<T>(term) : Color<T>(0),
                             textured ? Color<T>(mat.emissive) : Color<T>(0),
                             textured ? mat.emissive_texture : -1, textured ? mat.occlusion_texture : -1,
                             T(mat.occlusion_strength), bumpy ? mat.normal_texture : -1, T(mat.normal_scale),
                             metal_rough ? mat.metal_rough_texture : -1, T(mat.metallic), T(mat.roughness)});
        f.textured |= textured;
        f.metal_rough |= metal_rough;
        // (Its exponent varies per hit: std::pow.)
        f.fractional_exponents |= (whole < 0 || metal_rough) && fx.specular;
        if (whole > 0) f.exponent_bits = std::max(f.exponent_bits, int(std::bit_width(unsigned(whole))));
    }

    if (f.textured) f.textures = scene.textures;
    // Footprints are worked out only where a texture the shading reads may
    // be seen from far away, and mipmaps are not switched off.
    auto minifies = [&](int t) { return plan.mipmaps && t >= 0 && scene.textures[size_t(t)].minifies(); };
    for (const MaterialShading<T>& m : f.shading)
        f.minified |= minifies(m.texture) || minifies(m.emissive_texture) || minifies(m.occlusion_texture) ||
                      minifies(m.normal_texture) || minifies(m.metal_rough_texture);
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
                                 Vec3<T>(l.axis), T(l.max_angle), T(l.inner_angle), l.gltf_cone});
        // theta never exceeds pi, so a cone that wide needs no test.
        const bool cone_test = !plan.pruned || l.max_angle < 3.14159265358979323846;
        f.spot_cones.push_back(f.spot_lights.back().cone(cone_test ? T(l.max_angle) : kInfinity<T>));
        add_terms(f.spot_terms, l.color, l.on ? 1.0 : 0.0);  // x falloff
    }
    return f;
}

template struct FlatScene<float>;
template struct FlatScene<double>;

}  // namespace fh
