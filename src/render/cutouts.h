// Cutouts (glTF's alphaMode MASK, and BLEND for shadow rays): a surface
// that is there only where its alpha reaches the cutoff -- a leaf's outline
// on a quad. A ray that meets
// a hole goes on through it to the next surface, so camera rays see what is
// behind and shadow rays let light through: a leaf casts a leaf's shadow.
//
// Only instances have cutouts (glTF meshes are instances): the walk of a
// cut-out instance's mesh is followed by past_cutouts, which takes the rays
// whose nearest hits are holes on from just past them, together, until each
// meets a solid point or nothing. The walks of every other mesh are unchanged.
#pragma once

#include "core/offset.h"
#include "render/packet_intersect.h"
#include "scene/texture.h"

namespace fh {

// A ray crossing more holes than this in one mesh stops at the last one,
// as if it were solid: a bound on the work of one ray (docs/gltf.md).
inline constexpr int kMaxCutoutLayers = 64;

// Where a material's surface is: alpha times its texture's alpha (when it
// has one) times the mesh's vertex alpha (when it has them) at least cutoff.
// A BLEND material (blend) is see-through instead, alpha its opacity, for
// camera and reflection rays (render/shading.h); for shadow rays it is a
// cutout at 0.5.
struct Cutout {
    Texture texture;  // image null: alpha alone
    float alpha = 1;
    float cutoff = 0.5f;
    bool blend = false;
};

// Per lane: the surface's alpha at the points p of triangle prim (in the
// mesh's space).
template <typename T>
FH_HOT_INLINE Lanes<T> alpha_at(const FlatGeometry<T>& mesh, const Cutout& cut, int prim, const Vec3Lanes<T>& p) {
    Lanes<T> alpha = splat(T(cut.alpha));
    const bool texels = cut.texture.image && !mesh.uvs.empty();
    if (!texels && mesh.alphas.empty()) return alpha;
    Lanes<T> b1, b2;
    mesh.weights_at(prim, p, b1, b2);
    if (texels) {
        Lanes<T> u, v;
        mesh.uv_at(prim, b1, b2, u, v);
        alpha = alpha * cut.texture.sample<T>(u, v).a;
    }
    if (!mesh.alphas.empty()) alpha = alpha * mesh.alpha_at(prim, b1, b2);
    return alpha;
}

// Per lane: whether the surface is there at the points p of the active
// lanes' triangles prim (in the mesh's space), one triangle at a time.
template <typename T>
FH_HOT_INLINE LaneInts<T> solid_at(const FlatGeometry<T>& mesh, const Cutout& cut, const LaneInts<T>& prim,
                                   const Vec3Lanes<T>& p, LaneInts<T> active) {
    const bool texels = cut.texture.image && !mesh.uvs.empty();
    if (!texels && mesh.alphas.empty()) return cut.alpha >= cut.cutoff ? active : LaneInts<T>{};
    LaneInts<T> solid{};
    while (any(active)) {
        int first = 0;
        while (!active[first]) ++first;
        const LaneInts<T> same = active & (prim == prim[first]);
        solid |= same & (alpha_at(mesh, cut, int(prim[first]), p) >= T(cut.cutoff));
        active &= ~same;
    }
    return solid;
}

// m: the nearest hits of the active rays on `mesh` below `limit`. The rays
// whose hits are holes go on from just past them -- from the far side of
// the face, by the offset secondary rays use -- together, as a packet,
// until each meets a solid point, which becomes its hit, or nothing below
// its limit (kNoHit).
template <typename T>
__attribute__((noinline)) HitLanes<T> past_cutouts(const FlatGeometry<T>& mesh, const Cutout& cut,
                                                   RayPacket<T> ray, const LaneInts<T>& active,
                                                   const Lanes<T>& limit, HitLanes<T> m) {
    LaneInts<T> open = active & (m.prim != kNoHit);
    Lanes<T> travelled = splat(T(0));
    for (int layer = 1; layer < kMaxCutoutLayers && any(open); ++layer) {
        const Vec3Lanes<T> p = ray.at(select(open, m.t, splat(T(0))));
        const LaneInts<T> hole = open & ~solid_at(mesh, cut, m.prim, p, open);
        if (none(hole)) break;
        // Each hole's face normal, turned away from the ray: the new origin
        // lies just beyond the face.
        Vec3Lanes<T> beyond = ray.direction;
        for (int lane = 0; lane < kLanes<T>; ++lane) {
            if (!hole[lane]) continue;
            const Vec3<T> n = mesh.triangles[size_t(mesh.ids.triangle_index(int(m.prim[lane])))].normal;
            const T side = glm::dot(n, ray.direction.lane(lane)) > T(0) ? T(1) : T(-1);
            beyond.x[lane] = side * n.x, beyond.y[lane] = side * n.y, beyond.z[lane] = side * n.z;
        }
        const Vec3Lanes<T> origin = offset_origin(p, beyond);
        travelled = select(hole, travelled + dot(origin - ray.origin, ray.direction), travelled);
        ray.origin = select(hole, origin, ray.origin);
        const HitLanes<T> next = closest_hits_within(mesh, ray, hole, select(hole, limit - travelled, splat(T(0))));
        m.t = select(hole, next.t, m.t);
        m.prim = select(hole, next.prim, m.prim);
        open = hole & (next.prim != kNoHit);
    }
    const LaneInts<T> hit = active & (m.prim != kNoHit);
    m.t = select(hit, travelled + m.t, m.t);
    return m;
}

}  // namespace fh
