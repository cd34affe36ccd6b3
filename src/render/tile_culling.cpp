#include "render/tile_culling.h"

#include <cmath>

namespace fh {

TileFrustum::TileFrustum(const CameraRays<double>& camera, double x0, double x1, double y0, double y1) {
    // The corners in order around the rectangle; each side plane holds two
    // neighbouring corner rays A and B. Its normal dA x (oB + dB - oA) is
    // dA x dB when the rays share the eye, and d x (oB - oA) when they are
    // parallel.
    const Ray<double> corner[4] = {camera.generate(x0, y0), camera.generate(x1, y0),
                                   camera.generate(x1, y1), camera.generate(x0, y1)};
    const Ray<double> mid = camera.generate((x0 + x1) / 2, (y0 + y1) / 2);
    const dvec3 inside = mid.origin + mid.direction;
    for (int i = 0; i < 4; ++i) {
        const Ray<double>& a = corner[i];
        const Ray<double>& b = corner[(i + 1) % 4];
        dvec3 n = glm::normalize(glm::cross(a.direction, b.origin + b.direction - a.origin));
        if (glm::dot(n, inside - a.origin) < 0) n = -n;
        point_[i] = a.origin;
        normal_[i] = n;
    }
}

bool TileFrustum::may_hit(const dvec3& center, double radius) const {
    for (int i = 0; i < 4; ++i) {
        const dvec3 to_center = center - point_[i];
        const double padded = radius + 1e-4 * (radius + glm::length(to_center));
        // NaN (a degenerate plane) compares false: the sphere is kept.
        if (glm::dot(normal_[i], to_center) < -padded) return false;
    }
    return true;
}

template <typename T>
void cull_to_frustum(const FlatScene<T>& scene, const TileFrustum& frustum, PrimitiveSubset& out) {
    out.spheres.clear();
    out.clusters.clear();
    for (size_t i = 0; i < scene.spheres.size(); ++i)
        if (frustum.may_hit(dvec3(scene.spheres[i].center), double(scene.spheres[i].radius)))
            out.spheres.push_back(int(i));
    for (size_t i = 0; i < scene.clusters.size(); ++i)
        if (frustum.may_hit(dvec3(scene.clusters[i].center), std::sqrt(double(scene.clusters[i].radius2))))
            out.clusters.push_back(int(i));
}

template void cull_to_frustum(const FlatScene<float>&, const TileFrustum&, PrimitiveSubset&);
template void cull_to_frustum(const FlatScene<double>&, const TileFrustum&, PrimitiveSubset&);

}  // namespace fh
