// Material (report 3, Table 1): a colour and a strength for each of the
// ambient, diffuse and specular terms, a Phong exponent, and glazing.
#pragma once

#include <cmath>

#include "core/fast_math.h"

namespace fh {

template <typename T>
struct Material {
    Color<T> ambient_color{0};
    Color<T> diffuse_color{0};
    Color<T> specular_color{0};
    T ambient = 0;
    T diffuse = 0;
    T specular = 0;
    T phong_exponent = 1;
    bool glazed = false;
    T reflectivity = 0;  // weight of the reflected colour when glazed
    // Light the surface gives off itself (0..255 a channel, added as it is,
    // lit or not: a glTF material's emissive). The report's materials have none.
    Color<T> emissive{0};
    // A glTF material's base colour texture (into Scene::textures; -1:
    // none): its colour multiplies the ambient and diffuse colours per hit.
    int texture = -1;
    // Its emissive texture: its colour multiplies `emissive` per hit.
    int emissive_texture = -1;
    // Its occlusion texture (read linear, red channel R): the ambient term
    // is multiplied by 1 + occlusion_strength (R - 1) per hit.
    int occlusion_texture = -1;
    T occlusion_strength = 1;
    // Its normal texture (read linear): the shading normal is turned per
    // hit to the texel's direction in the triangle's tangent frame, its
    // tangential part times normal_scale (render/normal_map.h).
    int normal_texture = -1;
    T normal_scale = 1;
    // Its metallic-roughness texture (read linear): per hit, metalness
    // metallic x B and roughness roughness x G (the factors glTF's) take the
    // place of the factors in the mapping onto the terms above
    // (gltf/gltf_materials.cpp, render/metal_rough.h).
    int metal_rough_texture = -1;
    T metallic = 0, roughness = 1;

    // A hit may mirror: glazed with some reflectivity, or a metal whose
    // metallic-roughness texture may polish any hit (metallic > 0.5).
    bool may_mirror() const { return (glazed && reflectivity > 0) || (metal_rough_texture >= 0 && metallic > 0.5); }
    // glTF's alphaMode MASK: the surface is there only where its alpha --
    // `alpha` times the texture's -- is at least alpha_cutoff; elsewhere
    // camera and shadow rays pass through it.
    bool cutout = false;
    T alpha = 1;
    T alpha_cutoff = T(0.5);
    // glTF's alphaMode BLEND: the surface is see-through, its alpha (as
    // above) the share of its own colour in what a camera or reflection
    // ray brings back, the rest from behind it; a shadow ray through it
    // carries (1 - alpha) of its light on (render/cutouts.h light_through).
    bool blend = false;
};

// The exponent as a whole number, so shading can use repeated squaring; -1
// when it is not one (or above kWholePowerLimit).
inline int whole_exponent(double e) {
    return (e >= 0 && e <= kWholePowerLimit && std::floor(e) == e) ? int(e) : -1;
}

}  // namespace fh
