// glTF's metallic-roughness texture, per hit (docs/gltf.md, "Materials"):
// metalness m and roughness r -- the factors times the texel's blue and
// green, read as data -- go through the same mapping onto the report's terms
// as a material's factors do (gltf/gltf_materials.cpp, material_of), lane
// by lane:
//   diffuse strength   (1 - m) + m r
//   specular strength  (0.04 + 0.96 m)(1 - r), its colour m c + (1 - m) 255
//   Phong exponent     min(2 / a^2 - 2, 10000), a = max(r^2, 0.01)
//   glazed where m > 0.5 and r < 0.5, reflectivity m (1 - r)^2
#pragma once

#include "core/packet.h"
#include "render/flat_geometry.h"
#include "scene/texture.h"

namespace fh {

template <typename T>
FH_HOT_INLINE Lanes<T> diffuse_strength(const Lanes<T>& m, const Lanes<T>& r) {
    return (T(1) - m) + m * r;
}

template <typename T>
FH_HOT_INLINE Lanes<T> specular_strength(const Lanes<T>& m, const Lanes<T>& r) {
    return (T(0.04) + T(0.96) * m) * (T(1) - r);
}

template <typename T>
FH_HOT_INLINE Lanes<T> phong_exponent(const Lanes<T>& r) {
    const Lanes<T> a = max(r * r, splat(T(0.01)));
    return min(T(2) / (a * a) - T(2), splat(T(10000)));
}

template <typename T>
FH_HOT_INLINE LaneInts<T> polished(const Lanes<T>& m, const Lanes<T>& r) {
    return (m > T(0.5)) & (r < T(0.5));
}

template <typename T>
FH_HOT_INLINE Lanes<T> mirror_share(const Lanes<T>& m, const Lanes<T>& r) {
    return m * (T(1) - r) * (T(1) - r);
}

// Kept out of line, as the two below: inlined into the shader's loop over
// lights, this code made scenes without such textures (the placed engine)
// 20% slower.

// Each hit's metalness and roughness: the factors times the texel's blue
// and green, at points `at`.
template <typename T>
__attribute__((noinline)) void metal_rough_at(const Texture& texture, const TrianglePoint<T>& at, T metallic,
                                              T roughness, Lanes<T>& metal, Lanes<T>& rough) {
    const TexelLanes<T> c = texture.template sample<T>(at.u, at.v, at.footprint);  // a data texture: n / 255
    metal = metallic * c.b;
    rough = roughness * c.g;
}

// One light's colour terms and Phong exponents at hits of metalness `metal`
// and roughness `rough` (unit, tinted, white: its LightTerms' diffuse_unit,
// tinted and white).
template <typename T>
__attribute__((noinline)) void metal_rough_terms(const Lanes<T>& metal, const Lanes<T>& rough, const Color<T>& unit,
                                                 const Color<T>& tinted, const Color<T>& white, ColorLanes<T>& kd,
                                                 ColorLanes<T>& ks, Lanes<T>& exponent) {
    kd = diffuse_strength<T>(metal, rough) * unit;
    ks = specular_strength<T>(metal, rough) * (metal * tinted + (T(1) - metal) * white);
    exponent = phong_exponent<T>(rough);
}

}  // namespace fh
