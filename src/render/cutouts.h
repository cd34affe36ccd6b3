// Cutouts (glTF's alphaMode MASK): a surface that is there only where its
// alpha reaches the cutoff -- a leaf's outline on a quad. A ray that meets
// a hole goes on through it to the next surface, so camera rays see what is
// behind and shadow rays let light through: a leaf casts a leaf's shadow.
//
// Only instances have cutouts (glTF meshes are instances): the walk of a
// cut-out instance's mesh is followed by past_cutouts, which takes each ray
// whose nearest hit is a hole on from just past it, one ray at a time, until
// a solid point or nothing. The walks of every other mesh are unchanged.
#pragma once

#include "core/offset.h"
#include "render/packet_intersect.h"
#include "scene/texture.h"

namespace fh {

// A ray crossing more holes than this in one mesh stops at the last one,
// as if it were solid: a bound on the work of one ray (docs/gltf.md).
inline constexpr int kMaxCutoutLayers = 64;

// Where a material's surface is: alpha times its texture's alpha (when it
// has one) at least cutoff.
struct Cutout {
    Texture texture;  // image null: alpha alone
    float alpha = 1;
    float cutoff = 0.5f;

    bool solid(double u, double v) const {
        const float a = texture.image ? alpha * texture.sample(u, v)[3] : alpha;
        return a >= cutoff;
    }
};

// Whether the surface of triangle `prim` of `mesh` is there at point p.
template <typename T>
bool solid_at(const FlatGeometry<T>& mesh, const Cutout& cut, int prim, const Vec3<T>& p) {
    if (!cut.texture.image || mesh.uvs.empty()) return cut.solid(0, 0);
    Lanes<T> u, v;
    mesh.uv_at(prim, Vec3Lanes<T>::splat(p), u, v);
    return cut.solid(double(u[0]), double(v[0]));
}

// m: the nearest hits of the active rays on `mesh` below `limit`. Each ray
// whose hit is a hole is taken on past it (from the far side of the face,
// by the offset secondary rays use) until a solid point, which becomes its
// hit, or nothing below its limit (kNoHit).
template <typename T>
__attribute__((noinline)) HitLanes<T> past_cutouts(const FlatGeometry<T>& mesh, const Cutout& cut,
                                                   const RayPacket<T>& ray, const LaneInts<T>& active,
                                                   const Lanes<T>& limit, HitLanes<T> m) {
    for (int lane = 0; lane < kLanes<T>; ++lane) {
        if (!active[lane] || m.prim[lane] == kNoHit) continue;
        const Vec3<T> d = ray.direction.lane(lane);
        Ray<T> r = ray.lane(lane);
        T t = m.t[lane], travelled = 0;
        int prim = int(m.prim[lane]);
        for (int layer = 1; layer < kMaxCutoutLayers && prim != kNoHit; ++layer) {
            if (solid_at(mesh, cut, prim, r.origin + t * d)) break;
            const SurfacePoint<T> hole = mesh.surface(r, {t, prim, -1});
            const Vec3<T> o = offset_origin(hole.point, -hole.normal);
            travelled += glm::dot(o - r.origin, d);
            r = {o, d};
            const HitLanes<T> next =
                closest_hits_within(mesh, RayPacket<T>::splat(r), first_lanes<T>(1), splat(limit[lane] - travelled));
            t = next.t[0];
            prim = int(next.prim[0]);
        }
        m.t[lane] = prim == kNoHit ? limit[lane] : travelled + t;
        m.prim[lane] = prim;
    }
    return m;
}

}  // namespace fh
