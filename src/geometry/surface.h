// Where a primitive's surface is, as shading reads it after a hit: enough to
// put the hit point back onto the surface and to find its normal there. Each
// shape gives its own (Sphere::surface, Plane::surface, ...).
#pragma once

#include "core/packet.h"

namespace fh {

// How a point is put back onto the surface.
enum class SurfaceForm : std::uint8_t {
    flat,   // onto a plane through `anchor` with normal `normal` (planes, triangles, disks)
    round,  // onto a sphere about `anchor` with radius `radius`
};

template <typename T>
struct PrimitiveSurface {
    SurfaceForm form = SurfaceForm::flat;
    Vec3<T> anchor{0};  // round: the centre; flat: a point on it
    Vec3<T> normal{0};  // flat: the unit normal
    T radius = 0;       // round
    int material = -1;
    int smooth = -1;    // a smooth triangle: its index in FlatGeometry::smooth_triangles

    static PrimitiveSurface flat_through(const Vec3<T>& point, const Vec3<T>& unit_normal, int material) {
        return {SurfaceForm::flat, point, unit_normal, T(0), material};
    }
    static PrimitiveSurface round_about(const Vec3<T>& center, T radius, int material) {
        return {SurfaceForm::round, center, Vec3<T>(0), radius, material};
    }

    // For points p on the surface (up to the rounding of a ray's travel): p
    // projected back onto it -- its error is then a few ulps of its own
    // coordinates, not of the ray's travel -- and the unit geometric normal
    // there (facing outward, not yet the ray).
    FH_HOT_INLINE void project(const Vec3Lanes<T>& p, Vec3Lanes<T>& point, Vec3Lanes<T>& unit_normal) const {
        if (form == SurfaceForm::round) {
            unit_normal = normalize(p - anchor);
            point = anchor + radius * unit_normal;
        } else {
            unit_normal = Vec3Lanes<T>::splat(normal);
            point = p - dot(normal, p - anchor) * normal;
        }
    }

    // One point (tests): the same formula with p in every lane.
    void project(const Vec3<T>& p, Vec3<T>& point, Vec3<T>& unit_normal) const {
        Vec3Lanes<T> q, n;
        project(Vec3Lanes<T>::splat(p), q, n);
        point = q.lane(0);
        unit_normal = n.lane(0);
    }
};

}  // namespace fh
