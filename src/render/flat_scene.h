// The scene as the tracer reads it: its shapes (render/flat_geometry.h), only
// the lights that can contribute, and each light's colour products with each
// material computed once per frame instead of once per ray. Built from a
// Scene for one frame; tracing allocates nothing.
#pragma once

#include <memory>
#include <vector>

#include "render/effect_plan.h"
#include "render/flat_geometry.h"
#include "render/instance_set.h"

namespace fh {

// What shading reads about a material, in the tracer's type.
template <typename T>
struct MaterialShading {
    // The ambient term, summed over the ambient lights, plus the emissive
    // colour: what a hit gets whose colour nothing tints.
    Color<T> ambient{0};
    bool glazed = false;  // a hit sends a reflection ray
    T reflectivity = 0;
    T exponent = 0;       // Phong
    bool whole_exponent = true;  // the exponent is whole and at most kWholePowerLimit
    // A textured material (FlatScene::textures; -1: none): its texel colour
    // multiplies the ambient term alone (tinted_ambient) and the diffuse
    // terms, and its emissive colour is added after. So too the vertex
    // colours of a mesh that has them (with or without a texture). Both
    // are 0 for a material nothing tints.
    int texture = -1;
    Color<T> tinted_ambient{0};
    Color<T> emissive{0};
    // Its emissive texture multiplies `emissive`; its occlusion texture's
    // red channel R the tinted ambient term, by 1 + occlusion_strength (R - 1)
    // (FlatScene::textures; -1: none).
    int emissive_texture = -1;
    int occlusion_texture = -1;
    T occlusion_strength = 1;
    // Its normal texture turns the shading normal (render/normal_map.h;
    // -1: none, or no light or mirror would show it).
    int normal_texture = -1;
    T normal_scale = 1;
    // Its metallic-roughness texture: metalness metallic x B and roughness
    // roughness x G per hit, mapped onto the terms by render/metal_rough.h
    // (-1: none, or nothing lit or mirrored shows it).
    int metal_rough_texture = -1;
    T metallic = 0, roughness = 1;
};

// intensity * strength * (light colour (.) material colour), for one light and
// one material; the spot light's falloff multiplies it per point.
// For a material with a metallic-roughness texture, whose strengths and
// highlight's tint vary per hit, the products before them: intensity x
// (light colour (.) diffuse colour) for the diffuse term (0 when it is not
// simulated) and for the highlight's tint, and intensity x (light colour x
// 255) for its white.
template <typename T>
struct LightTerms {
    Color<T> diffuse{0};
    Color<T> specular{0};
    Color<T> diffuse_unit{0}, tinted{0}, white{0};
};

template <typename T>
struct FlatScene {
    // Shared by every frame whose shapes do not move.
    std::shared_ptr<const FlatGeometry<T>> geometry;
    // The scene's instances (nullptr: none); shared by every frame that moves none of them.
    std::shared_ptr<const InstanceSet<T>> instances;
    std::vector<MaterialShading<T>> shading;    // by material
    std::vector<DirectionalLight<T>> directional_lights;
    std::vector<SpotLight<T>> spot_lights;
    std::vector<SpotCone<T>> spot_cones;  // by spot light: what SpotLight::radiance_at needs of its cone
    // Each light's colour products with each material: [light * shading.size() + material].
    std::vector<LightTerms<T>> directional_terms;
    std::vector<LightTerms<T>> spot_terms;
    std::vector<Texture> textures;  // Scene::textures, when some material is textured
    bool textured = false;          // some material is (instances only: glTF's)
    bool minified = false;          // some texture the shading reads is read by its footprint (Texture::minifies; never with mipmaps off)
    bool blended = false;           // some instance's material is see-through (glTF's BLEND)
    bool metal_rough = false;       // some material's metallic-roughness texture is read
    bool fractional_exponents = false;  // some material has whole == false: std::pow needed
    int exponent_bits = 0;              // bits of the largest whole exponent
    EffectPlan plan;

    // Only what the plan simulates: lights it uses, terms of its effects.
    // pool: the BVH is built on it (nullptr: on the calling thread).
    static FlatScene build(const Scene& scene, const EffectPlan& plan, ThreadPool* pool = nullptr);
    // The same over geometry and instances already built from this scene's
    // shapes (a frame of a movie): only lights and materials are flattened.
    static FlatScene build(const Scene& scene, const EffectPlan& plan,
                           std::shared_ptr<const FlatGeometry<T>> geometry,
                           std::shared_ptr<const InstanceSet<T>> instances);
};

extern template struct FlatScene<float>;
extern template struct FlatScene<double>;

}  // namespace fh
