// How much of a texture one pixel covers where its ray hits: the level of
// detail that picks a texture's mipmap (scene/texture.h). A ray cone (after
// Akenine-Möller et al., "Texture Level of Detail Strategies for Real-Time
// Ray Tracing", Ray Tracing Gems, 2019): each camera ray stands for a cone
// as wide as its pixel (times kConeShare below), whose width at distance t is
//     width(t) = width0 + spread t
// -- perspective: width0 = 0 and spread = the pixel's height on the image
// plane over projection_distance; orthographic: width0 = the pixel's
// height and spread = 0; both divided by sqrt(samples per pixel), as each
// sample stands for that share of the pixel (an adaptive frame's refined
// pixels: by the samples they get). A mirror or a see-through
// surface passes the cone on with t counted along the whole path, as a flat
// mirror would (a curved one's focusing is ignored).
//
// On a triangle of world area A, at an angle theta to the ray, a width w
// across the ray covers w / cos(theta) of the surface, and the texture maps
// space to (u, v) by the root of the ratio of areas, sqrt(A_uv / A):
//     footprint = w sqrt(A_uv / A) / cos(theta)
// in (u, v) units, and lod = log2 footprint (Texture::sample adds log2 of
// the texture's size). An instance's triangle is known in its mesh's
// space, edges e1, e2, face normal N = e1 x e2; the instance maps it to
// the world by a linear map L (to_world), so the world's face normal is
// det(L) L^-T N, and the ray's world direction d is d_o = L^-1 d there:
//     2 A      = |det L| |L^-T N|,     2 A_uv = |det_uv|,
//     cos(theta) = |N . d_o| / |L^-T N|   (N_w . d = det(L) N . d_o)
//     footprint = w sqrt(|det_uv| |L^-T N| / |det L|) / |N . d_o|
// -- for any map, stretched or mirrored (for L = s R it is the mesh-space
// footprint scaled by 1 / s). Where the ray grazes the face (N . d_o = 0)
// lod is +infinity (the smallest level); where the triangle has no area in
// the image, -infinity (a point): never NaN from a real cone.
#pragma once

#include <algorithm>
#include <cmath>

#include "render/flat_geometry.h"
#include "render/instance_set.h"
#include "scene/camera.h"

namespace fh {

// The cone's width as a share of the pixel's: 1/sqrt(2), half a level
// sharper than the pixel itself. Trilinear reads blend each level's texels
// with their neighbours' over about twice a texel, so a cone the pixel's
// full width blurs more than the pixel's own box of samples does. On a
// checkerboard floor receding to the horizon (400 x 225, 1 sample, against
// 256 samples without mipmaps) a full width gives 26.2 dB, 1/sqrt(2) 27.8,
// 1/2 26.6; without mipmaps 17.6 (docs/gltf.md, "Textures").
inline constexpr double kConeShare = 0.70710678118654752;

template <typename T>
struct PixelCone {
    T width = 0;   // across a camera ray's pixel where it starts
    T spread = 0;  // the growth of that width per unit of distance

    static PixelCone of(const Camera& camera, int samples_per_pixel) {
        const double pixel =
            kConeShare * 2 * camera.half_height / camera.height / std::sqrt(double(std::max(1, samples_per_pixel)));
        if (camera.projection == Projection::perspective) return {T(0), T(pixel / camera.projection_distance)};
        return {T(pixel), T(0)};
    }

    FH_HOT_INLINE Lanes<T> at(const Lanes<T>& distance) const { return width + spread * distance; }
};

// lod at hits on triangle `prim` of instance `instance`'s mesh (uvs not
// empty) of rays whose directions in the mesh's space are d_object, their
// cones `width` wide there in world units. Only the `lanes` are worked out;
// the others take the first one's lod, so that they ask for no other
// level (their texels are not used). Out of line, as the
// metallic-roughness terms are (render/metal_rough.h): code inlined into
// the shader's loop costs the scenes that never run it.
template <typename T>
__attribute__((noinline)) Lanes<T> footprint_lod(const FlatGeometry<T>& mesh, int prim,
                                                 const FlatInstance<T>& instance, const Vec3Lanes<T>& d_object,
                                                 const Lanes<T>& width, const LaneInts<T>& lanes) {
    const UvEdges<T> c = mesh.uv_edges(prim);
    const Vec3<T> normal = glm::cross(c.e1, c.e2);
    const AffineMap<T>& to_world = instance.to_world;
    const T det = std::abs(glm::dot(to_world.x, glm::cross(to_world.y, to_world.z)));
    const AffineMap<T>& n = instance.normal_to_world;
    const Vec3<T> turned = normal.x * n.x + normal.y * n.y + normal.z * n.z;  // L^-T N
    const T root = std::sqrt(std::abs(c.det) * glm::length(turned) / det);
    const Lanes<T> footprint = width * root / abs(dot(Vec3Lanes<T>::splat(normal), d_object));
    Lanes<T> lod = footprint;  // overwritten lane by lane
    int first = -1;
    for_each_lane(lanes, [&](int i) {
        lod[i] = std::log2(footprint[i]);
        if (first < 0) first = i;
        return false;
    });
    return select(lanes, lod, splat(lod[first < 0 ? 0 : first]));
}

}  // namespace fh
