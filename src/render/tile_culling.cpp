#include "render/tile_culling.h"

#include <algorithm>
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
void cull_to_frustum(const FlatGeometry<T>& geometry, const TileFrustum& frustum, PrimitiveSubset& out) {
    out.prims.clear();
    out.walk_bvh = false;
    const Bvh& bvh = geometry.bvh;
    if (bvh.empty()) return;
    const int spheres = int(geometry.spheres.size());
    // A box as its bounding sphere, a triangle as the sphere around its box.
    auto box_may_hit = [&](const dvec3& lo, const dvec3& hi) {
        return frustum.may_hit(0.5 * (lo + hi), 0.5 * glm::length(hi - lo));
    };
    int stack[160];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BvhNode& n = bvh.nodes[size_t(stack[--top])];
        if (!box_may_hit(dvec3(n.lo[0], n.lo[1], n.lo[2]), dvec3(n.hi[0], n.hi[1], n.hi[2]))) continue;
        if (!n.leaf()) {
            stack[top++] = n.first;
            stack[top++] = n.second;
            continue;
        }
        for (int k = n.first; k < n.first + n.count; ++k) {
            const int i = bvh.prims[size_t(k)];
            bool may = false;
            if (i < spheres) {
                may = frustum.may_hit(dvec3(geometry.spheres[size_t(i)].center), double(geometry.spheres[size_t(i)].radius));
            } else {
                const Triangle<T>& t = geometry.triangles[size_t(i - spheres)];
                const dvec3 a(t.v0), b(t.v1), c(t.v2);
                may = box_may_hit(glm::min(a, glm::min(b, c)), glm::max(a, glm::max(b, c)));
            }
            if (!may) continue;
            if (out.prims.size() == kMaxSubset) {  // too many to list: walk the BVH
                out.prims.clear();
                out.walk_bvh = true;
                return;
            }
            out.prims.push_back(i);
        }
    }
    std::sort(out.prims.begin(), out.prims.end());
}

template void cull_to_frustum(const FlatGeometry<float>&, const TileFrustum&, PrimitiveSubset&);
template void cull_to_frustum(const FlatGeometry<double>&, const TileFrustum&, PrimitiveSubset&);

}  // namespace fh
