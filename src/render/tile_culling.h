// Which primitives a tile's camera rays can hit. The camera rays through a
// rectangle of the image lie inside the frustum of its four corner rays: a
// pyramid from the eye (perspective) or a prism (orthographic). A sphere --
// or the sphere around a BVH node's or a triangle's box -- farther than its radius outside
// one of the frustum's four side planes is hit by none of them, so the
// tile's first hits skip it: four plane tests per primitive per tile instead
// of a test per packet. Planes, infinite, are always tested.
#pragma once

#include <vector>

#include "render/flat_geometry.h"
#include "scene/camera.h"

namespace fh {

// The frustum's side planes of the pixels [x0, x1) x [y0, y1) (continuous
// pixel coordinates, as CameraRays takes them).
class TileFrustum {
public:
    TileFrustum(const CameraRays<double>& camera, double x0, double x1, double y0, double y1);

    // False only if no ray of the frustum can meet the sphere. The radius is
    // padded by a relative 1e-4, far above the rounding of rays in float.
    bool may_hit(const dvec3& center, double radius) const;

private:
    dvec3 point_[4];   // a point of each side plane
    dvec3 normal_[4];  // unit, pointing inside
};

// The spheres and triangles of `geometry` the frustum may hit, into `out`: found
// by walking the BVH with the frustum; more than kMaxSubset of them and
// `out` says to walk the BVH per packet instead.
template <typename T>
void cull_to_frustum(const FlatGeometry<T>& geometry, const TileFrustum& frustum, PrimitiveSubset& out);

}  // namespace fh
