// How much of a texture one pixel covers where its ray hits: the ellipse
// a texture's mipmaps are read over (scene/texture.h). A ray cone (after
// Akenine-Möller et al., "Texture Level of Detail Strategies for Real-Time
// Ray Tracing", Ray Tracing Gems, 2019): each camera ray stands for a cone
// as wide as its pixel, whose width at distance t is
//     width(t) = width0 + spread t
// -- perspective: width0 = 0 and spread = the pixel's height on the image
// plane over projection_distance; orthographic: width0 = the pixel's
// height and spread = 0; both divided by sqrt(samples per pixel), as each
// sample stands for that share of the pixel (an adaptive frame's refined
// pixels: by the samples they get). A perspective ray theta off the
// camera's axis takes cos(theta) of that width: its pixel lies 1 /
// cos(theta) farther along it than the centre's, at the same size, so the
// pixel's side across the ray's plane with the axis looks cos(theta) as
// wide (the side in that plane, tilted too, cos^2(theta); a round cone
// takes the first, which measured best). On a plane facing the camera,
// every pixel's cone is then as wide as the centre's, as its pixels are.
// A mirror or a see-through surface passes the cone on with t counted
// along the whole path, as a flat mirror would (a curved one's focusing
// is ignored).
//
// On the triangle hit, the cone's round cross-section -- width w across
// the ray -- falls on the face as an ellipse: w wide across the ray, w /
// cos(theta) long along it. The texture maps the face to (u, v) linearly,
// by the gradients of u and v along it, so the footprint in the image is
// the ellipse those gradients make of it. It is worked out in the world,
// the triangle's edges e1, e2 carried there by its instance's linear map L
// (any map: stretched, sheared, mirrored), face normal n = e1 x e2:
//     a point p - v0 = a e1 + b e2 of the face has a = p . (e2 x n) / n.n,
//     b = p . (n x e1) / n.n, and (u, v) - (u0, v0) = a (du1, dv1) +
//     b (du2, dv2): the gradients gu, gv of u and v;
//     x1 = the unit vector along the face across the ray (d x n, or any
//     along the face for a ray along n), x2 = d x x1 across the ray too,
//     which falls on the face at p2 = x2 - d (n . x2) / (n . d);
//     the ellipse on the face has axes w x1 and w p2, end to end, and in
//     the image the conjugate diameters g1 = w (gu . x1, gv . x1) and
//     g2 = w (gu . p2, gv . p2)
// (its axes too where the map keeps angles, as most do). Each texture
// finds the axes in its own texels (scene/texture.h, UvFootprint). Where
// the ray grazes the face (n . d = 0) the footprint is infinite (the
// smallest level); where the triangle's coordinates meet at one point, a
// point; on a line, a line (read along it); where it has no area in the
// world, unknown (read as magnified): never NaN from a real cone.
#pragma once

#include <algorithm>
#include <cmath>

#include "render/flat_geometry.h"
#include "render/instance_set.h"
#include "scene/camera.h"

namespace fh {

// The cone is as wide as its pixel, as the paper has it. Measured at 1
// sample against 256 (400 x 225; docs/gltf.md, "Textures"), a checkerboard
// floor receding to the horizon gives 37.7 dB, against 36.3 at 0.85 of the
// pixel, 31.3 at 1/sqrt(2) and 32.5 at 1.2; the glTF demo's frame 110 is
// best at the full width too, BoxTextured (head-on faces) at 0.85 by 0.4
// dB. (Read at one level by the footprint's length, before reads along
// it, 1/sqrt(2) did best: 28.2 dB on the floor.) The cos(theta) off the
// axis took the floor, whose corners are 37 degrees off, to 39.1 dB;
// cos^1.5 (the pixel's solid angle) gave 38.4, cos^2 37.2.
template <typename T>
struct PixelCone {
    T width = 0;      // across a camera ray's pixel where it starts
    T spread = 0;     // the growth of that width per unit of distance
    Vec3<T> axis{0};  // perspective: the camera's unit axis (-w); else 0

    static PixelCone of(const Camera& camera, int samples_per_pixel) {
        const double pixel =
            2 * camera.half_height / camera.height / std::sqrt(double(std::max(1, samples_per_pixel)));
        if (camera.projection == Projection::perspective)
            return {T(0), T(pixel / camera.projection_distance), Vec3<T>(-camera_basis(camera.look_at, camera.up).w)};
        return {T(pixel), T(0)};
    }

    FH_HOT_INLINE Lanes<T> at(const Lanes<T>& distance) const { return width + spread * distance; }

    // The share of the width the camera rays along unit `direction` take:
    // cos(theta) off a perspective camera's axis, all of it otherwise.
    FH_HOT_INLINE Lanes<T> share(const Vec3Lanes<T>& direction) const {
        if (spread == T(0)) return splat(T(1));
        return dot(direction, Vec3Lanes<T>::splat(axis));
    }
};

// The footprints at hits on triangle `prim` of instance `instance`'s mesh
// (uvs not empty) of rays with world directions `direction`, their cones
// `width` wide there. Only the `lanes` are worked out; the others take the
// first one's, so that they ask for no other reads (their texels are not
// used). Out of line, as the metallic-roughness terms are
// (render/metal_rough.h): code inlined into the shader's loop costs the
// scenes that never run it.
template <typename T>
__attribute__((noinline)) UvFootprint<T> footprint_on(const FlatGeometry<T>& mesh, int prim,
                                                      const FlatInstance<T>& instance,
                                                      const Vec3Lanes<T>& direction, const Lanes<T>& width,
                                                      const LaneInts<T>& lanes) {
    // The triangle's gradients, once, in double: a small triangle's
    // n . n would underflow in float.
    const UvEdges<T> c = mesh.uv_edges(prim);
    const AffineMap<T>& l = instance.to_world;
    const glm::dvec3 lx(l.x), ly(l.y), lz(l.z);
    const glm::dvec3 e1 = double(c.e1.x) * lx + double(c.e1.y) * ly + double(c.e1.z) * lz;
    const glm::dvec3 e2 = double(c.e2.x) * lx + double(c.e2.y) * ly + double(c.e2.z) * lz;
    const glm::dvec3 n = glm::cross(e1, e2);
    const double nn = glm::dot(n, n);
    const glm::dvec3 ra = glm::cross(e2, n) / nn, rb = glm::cross(n, e1) / nn;
    const Vec3Lanes<T> gu = Vec3Lanes<T>::splat(Vec3<T>(double(c.du1) * ra + double(c.du2) * rb));
    const Vec3Lanes<T> gv = Vec3Lanes<T>::splat(Vec3<T>(double(c.dv1) * ra + double(c.dv2) * rb));
    const Vec3Lanes<T> normal = Vec3Lanes<T>::splat(Vec3<T>(n / std::sqrt(nn)));
    const Vec3Lanes<T> side = Vec3Lanes<T>::splat(Vec3<T>(glm::normalize(e1)));

    const Vec3Lanes<T> d = direction * (T(1) / sqrt(dot(direction, direction)));
    const Vec3Lanes<T> across = cross(d, normal);
    const Lanes<T> sin2 = dot(across, across);
    // (Along the normal, within a millionth of a radian: any side will do.)
    const Vec3Lanes<T> x1 = select(sin2 > T(1e-12), across * (T(1) / sqrt(sin2)), side);
    const Vec3Lanes<T> x2 = cross(d, x1);
    const Lanes<T> cosine = dot(normal, d);
    const Vec3Lanes<T> p2 = x2 - d * (dot(normal, x2) / cosine);
    const Lanes<T> g1u = width * dot(gu, x1), g1v = width * dot(gv, x1);
    const Lanes<T> g2u = width * dot(gu, p2), g2v = width * dot(gv, p2);
    // Not a real ellipse: grazing (+infinity), none in the world (NaN),
    // or none in the image (0) -- see UvFootprint.
    const LaneInts<T> grazing = cosine == T(0);
    const Lanes<T> extent = abs(g1u) + abs(g1v) + abs(g2u) + abs(g2v);
    const LaneInts<T> real = ~grazing & (extent > T(0)) & (extent < kInfinity<T>);
    const Lanes<T> zero = splat(T(0));
    UvFootprint<T> f{select(real, g1u, select(grazing | (extent == kInfinity<T>), splat(kInfinity<T>), extent)),
                     select(real, g1v, zero), select(real, g2u, zero), select(real, g2v, zero)};
    if (const unsigned bits = lane_bits(lanes)) {
        const int first = __builtin_ctz(bits);
        const LaneInts<T> others = ~lanes;
        f.g1u = select(others, splat(f.g1u[first]), f.g1u);
        f.g1v = select(others, splat(f.g1v[first]), f.g1v);
        f.g2u = select(others, splat(f.g2u[first]), f.g2u);
        f.g2v = select(others, splat(f.g2v[first]), f.g2v);
    }
    return f;
}

}  // namespace fh
