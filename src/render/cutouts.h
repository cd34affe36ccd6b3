// Cutouts (glTF's alphaMode MASK): a surface that is there only where its
// alpha reaches the cutoff -- a leaf's outline on a quad. A ray that meets
// a hole goes on through it to the next surface, so camera rays see what is
// behind and shadow rays let light through: a leaf casts a leaf's shadow.
// See-through surfaces (BLEND) let a shadow ray's light through in part:
// light_through.
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
// A BLEND material (blend) is see-through instead, alpha its opacity: camera
// and reflection rays go on past it (render/shading.h), shadow rays carry
// (1 - alpha) of their light on (light_through).
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

// Per lane: the surface's alpha (alpha_at) at the points p of the active
// lanes' triangles prim (in the mesh's space), one triangle at a time; 1 in
// the other lanes.
template <typename T>
FH_HOT_INLINE Lanes<T> alphas_at(const FlatGeometry<T>& mesh, const Cutout& cut, const LaneInts<T>& prim,
                                 const Vec3Lanes<T>& p, LaneInts<T> active) {
    const bool texels = cut.texture.image && !mesh.uvs.empty();
    if (!texels && mesh.alphas.empty()) return select(active, splat(T(cut.alpha)), splat(T(1)));
    Lanes<T> alpha = splat(T(1));
    while (any(active)) {
        int first = 0;
        while (!active[first]) ++first;
        const LaneInts<T> same = active & (prim == prim[first]);
        alpha = select(same, alpha_at(mesh, cut, int(prim[first]), p), alpha);
        active &= ~same;
    }
    return alpha;
}

// Per lane: whether the surface is there at the points p of the active
// lanes' triangles prim (in the mesh's space).
template <typename T>
FH_HOT_INLINE LaneInts<T> solid_at(const FlatGeometry<T>& mesh, const Cutout& cut, const LaneInts<T>& prim,
                                   const Vec3Lanes<T>& p, const LaneInts<T>& active) {
    return active & (alphas_at(mesh, cut, prim, p, active) >= T(cut.cutoff));
}

// The rays in `lanes`, whose hits m lie at p, moved on to just past those
// faces -- to their far side, by the offset secondary rays use; travelled
// grows by the distance each moved along its ray.
template <typename T>
FH_HOT_INLINE void step_past(const FlatGeometry<T>& mesh, const HitLanes<T>& m, const Vec3Lanes<T>& p,
                             const LaneInts<T>& lanes, RayPacket<T>& ray, Lanes<T>& travelled) {
    // Each face normal, turned away from the ray: the new origin lies just
    // beyond the face.
    Vec3Lanes<T> beyond = ray.direction;
    for (int lane = 0; lane < kLanes<T>; ++lane) {
        if (!lanes[lane]) continue;
        const Vec3<T> n = mesh.triangles[size_t(mesh.ids.triangle_index(int(m.prim[lane])))].normal;
        const T side = glm::dot(n, ray.direction.lane(lane)) > T(0) ? T(1) : T(-1);
        beyond.x[lane] = side * n.x, beyond.y[lane] = side * n.y, beyond.z[lane] = side * n.z;
    }
    const Vec3Lanes<T> origin = offset_origin(p, beyond);
    travelled = select(lanes, travelled + dot(origin - ray.origin, ray.direction), travelled);
    ray.origin = select(lanes, origin, ray.origin);
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
        step_past(mesh, m, p, hole, ray, travelled);
        const HitLanes<T> next = closest_hits_within(mesh, ray, hole, select(hole, limit - travelled, splat(T(0))));
        m.t = select(hole, next.t, m.t);
        m.prim = select(hole, next.prim, m.prim);
        open = hole & (next.prim != kNoHit);
    }
    const LaneInts<T> hit = active & (m.prim != kNoHit);
    m.t = select(hit, travelled + m.t, m.t);
    return m;
}

// Per lane: the fraction of light a see-through mesh lets along the active
// rays up to limit -- the product of (1 - alpha) over each of its surfaces a
// ray crosses (in any order: a product), walked one layer at a time as
// past_cutouts does. As there, a ray that has crossed 63 surfaces of one
// mesh stops at the 64th as if it were solid: no light.
template <typename T>
__attribute__((noinline)) Lanes<T> light_through(const FlatGeometry<T>& mesh, const Cutout& cut, RayPacket<T> ray,
                                                 const LaneInts<T>& active, const Lanes<T>& limit) {
    Lanes<T> through = splat(T(1));
    HitLanes<T> m = closest_hits_within(mesh, ray, active, limit);
    LaneInts<T> open = active & (m.prim != kNoHit);
    Lanes<T> travelled = splat(T(0));
    for (int layer = 1; any(open); ++layer) {
        if (layer == kMaxCutoutLayers) return select(open, splat(T(0)), through);
        const Vec3Lanes<T> p = ray.at(select(open, m.t, splat(T(0))));
        through = select(open, through * (T(1) - alphas_at(mesh, cut, m.prim, p, open)), through);
        open &= through > T(0);
        if (none(open)) break;
        step_past(mesh, m, p, open, ray, travelled);
        m = closest_hits_within(mesh, ray, open, select(open, limit - travelled, splat(T(0))));
        open &= m.prim != kNoHit;
    }
    return through;
}

}  // namespace fh
