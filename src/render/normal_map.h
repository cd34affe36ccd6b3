// glTF's normal texture (docs/gltf.md, "Normal textures"): a texel is a
// direction in the frame of the surface's tangent t, bitangent b and normal
// n -- (x, y, z) = 2 texel - 1, x along increasing u, y towards the image's
// up, z along n -- and the shading normal is turned to it:
//   n' = normalize(s x t + s y b + z n)
// with s the texture's scale, t the tangent made perpendicular to n and
// unit, b = w (n x t). The tangent is the mesh's (a glTF TANGENT, or made
// from its normals: scene/mesh_tangents.h), interpolated as its normals
// are, w its sign; a mesh without normals has none, and the triangle's
// own dP/du serves, w -1 where its coordinates are mirrored.
#pragma once

#include "core/packet.h"
#include "render/flat_geometry.h"
#include "scene/texture.h"

namespace fh {

// The turned normal at points `at` of triangle `prim` of `mesh` (uvs not
// empty), n the shading normal there (unit, outward, in the mesh's space).
// Lanes where the frame or the texel's direction vanish keep n: never NaN.
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> normal_mapped(const FlatGeometry<T>& mesh, int prim, const TrianglePoint<T>& at,
                                         const Vec3Lanes<T>& n, const Texture& texture, T scale) {
    Vec3Lanes<T> along;  // the tangent before it is made perpendicular to n
    T w;
    if (!mesh.tangents.empty()) {
        const TriangleTangents<T>& k = mesh.tangents_of(prim);
        along = (T(1) - at.b1 - at.b2) * k.t0 + at.b1 * k.t1 + at.b2 * k.t2;
        w = k.w;
    } else {
        Vec3<T> du;
        if (!mesh.tangent_of(prim, du, w)) return n;
        along = Vec3Lanes<T>::splat(du);
    }
    const TexelLanes<T> c = texture.template sample<T>(at.u, at.v, at.footprint);  // a data texture: n / 255
    const Lanes<T> x = scale * (T(2) * c.r - T(1)), y = scale * (T(2) * c.g - T(1)), z = T(2) * c.b - T(1);
    const Vec3Lanes<T> tangent = along - dot(n, along) * n;
    // t vanishes where n lies along the tangent (a normal far off its face,
    // a TANGENT of zero).
    const Lanes<T> length2 = dot(tangent, tangent);
    const Vec3Lanes<T> t = tangent * (T(1) / sqrt(length2));
    const Vec3Lanes<T> b = w * cross(n, t);
    const Vec3Lanes<T> turned = x * t + y * b + z * n;
    const Lanes<T> turned2 = dot(turned, turned);
    const LaneInts<T> good = (length2 > T(1e-6) * dot(along, along)) & (length2 > T(0)) & (turned2 > T(1e-12)) &
                             (turned2 < kInfinity<T>);
    return select(good, turned * (T(1) / sqrt(turned2)), n);
}

}  // namespace fh
