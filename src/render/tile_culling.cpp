#include "render/tile_culling.h"

#include <algorithm>
#include <cmath>

namespace fh {
namespace {

// The plane holding rays a and b (neighbouring corner rays, or two rays
// through one line of the image), facing the point `inside`. Its normal
// dA x (oB + dB - oA) is dA x dB when the rays share the eye, and
// d x (oB - oA) when they are parallel.
FrustumSide side_through(const Ray<double>& a, const Ray<double>& b, const dvec3& inside) {
    dvec3 n = glm::normalize(glm::cross(a.direction, b.origin + b.direction - a.origin));
    if (glm::dot(n, inside - a.origin) < 0) n = -n;
    return {a.origin, n};
}

FrustumSide flipped(const FrustumSide& s) { return {s.point, -s.normal}; }

// The margin of a point at offset d from a side's point: 1e-4 |d|, with
// the 1-norm (no square root), which is never below the length.
double margin(const dvec3& d) { return 1e-4 * (std::abs(d.x) + std::abs(d.y) + std::abs(d.z)); }

}  // namespace

TileFrustum::TileFrustum(const CameraRays<double>& camera, double x0, double x1, double y0, double y1) {
    // The corners in order around the rectangle; each side holds two
    // neighbouring corner rays.
    const Ray<double> corner[4] = {camera.generate(x0, y0), camera.generate(x1, y0),
                                   camera.generate(x1, y1), camera.generate(x0, y1)};
    const Ray<double> mid = camera.generate((x0 + x1) / 2, (y0 + y1) / 2);
    for (int i = 0; i < 4; ++i)
        sides_[i] = side_through(corner[i], corner[(i + 1) % 4], mid.origin + mid.direction);
}

bool TileFrustum::may_hit(const dvec3& center, double radius) const {
    for (const FrustumSide& s : sides_) {
        const dvec3 d = center - s.point;
        // NaN (a degenerate plane) compares false: the sphere is kept.
        if (glm::dot(s.normal, d) < -(radius + 1e-4 * radius + margin(d))) return false;
    }
    return true;
}

bool TileFrustum::may_hit(const dvec3& a, const dvec3& b, const dvec3& c) const {
    auto outside = [](const FrustumSide& s, const dvec3& p) {
        const dvec3 d = p - s.point;
        return glm::dot(s.normal, d) < -margin(d);
    };
    for (const FrustumSide& s : sides_)
        if (outside(s, a) && outside(s, b) && outside(s, c)) return false;
    return true;
}

TileFrustum::Overlap TileFrustum::overlap(const dvec3& lo, const dvec3& hi) const {
    const dvec3 center = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
    bool inside = true;
    for (const FrustumSide& s : sides_) {
        // The box's corner farthest along the normal is `reach` beyond its
        // centre; the nearest, as far behind it.
        const dvec3 d = center - s.point;
        const double along = glm::dot(s.normal, d);
        const double reach = glm::dot(glm::abs(s.normal), half);
        const double m = margin(d) + 1e-4 * (half.x + half.y + half.z);
        if (along + reach < -m) return Overlap::outside;
        inside = inside && along - reach > m;
    }
    return inside ? Overlap::inside : Overlap::across;
}

TileSides::TileSides(const CameraRays<double>& camera, int width, int height, int tile_size)
    : tile_size_(tile_size), width_(width), height_(height) {
    // A line at each multiple of the tile size, and at the image's far edge.
    for (int x = 0;; x = std::min(x + tile_size, width)) {
        const Ray<double> in = camera.generate(x + 1.0, height / 2.0);
        columns_.push_back(side_through(camera.generate(x, 0), camera.generate(x, height), in.origin + in.direction));
        if (x == width) break;
    }
    for (int y = 0;; y = std::min(y + tile_size, height)) {
        const Ray<double> in = camera.generate(width / 2.0, y + 1.0);
        rows_.push_back(side_through(camera.generate(0, y), camera.generate(width, y), in.origin + in.direction));
        if (y == height) break;
    }
}

int TileSides::line(int coordinate, int size) const {
    return coordinate == size ? (size + tile_size_ - 1) / tile_size_ : coordinate / tile_size_;
}

TileFrustum TileSides::frustum(int x0, int x1, int y0, int y1) const {
    return {columns_[size_t(line(x0, width_))], flipped(columns_[size_t(line(x1, width_))]),
            rows_[size_t(line(y0, height_))], flipped(rows_[size_t(line(y1, height_))])};
}

namespace {

// Primitive `id` (a shape or a triangle) may be hit by a ray of the frustum.
template <typename T>
bool may_hit(const FlatGeometry<T>& geometry, const TileFrustum& frustum, int id) {
    if (geometry.ids.is_triangle(id)) {
        const Triangle<T>& t = geometry.triangles[size_t(geometry.ids.triangle_index(id))];
        return frustum.may_hit(dvec3(t.v0), dvec3(t.v1), dvec3(t.v2));
    }
    return geometry.shapes.visit(size_t(id), [&](const auto& s) { return frustum.may_hit(s); });
}

}  // namespace

template <typename T>
void cull_to_frustum(const FlatGeometry<T>& geometry, const TileFrustum& frustum, PrimitiveSubset& out) {
    out.prims.clear();
    out.walk_bvh = false;
    const Bvh& bvh = geometry.bvh;
    if (bvh.empty()) return;
    auto give_up = [&out] {  // too many to list: walk the BVH
        out.prims.clear();
        out.walk_bvh = true;
    };
    int stack[160];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const BvhNode& n = bvh.nodes[size_t(stack[--top])];
        const TileFrustum::Overlap o =
            frustum.overlap(dvec3(n.lo[0], n.lo[1], n.lo[2]), dvec3(n.hi[0], n.hi[1], n.hi[2]));
        if (o == TileFrustum::Overlap::outside) continue;
        // Every primitive under a box inside the frustum would be kept: when
        // they are too many, there is no need to go down and count them.
        if (o == TileFrustum::Overlap::inside && out.prims.size() + size_t(n.below) > kMaxSubset) return give_up();
        // A big tree gets no further than its root: a tile over it almost
        // never finds as few as kMaxSubset, and the frustum walk that finds
        // that out cost more than the lists it found saved (docs/speed.md, log).
        if (n.below > kMaxCulledPrimitives) return give_up();
        if (!n.leaf()) {
            stack[top++] = n.first;
            stack[top++] = n.second;
            continue;
        }
        for (int k = n.first; k < n.first + n.count; ++k) {
            const int id = bvh.prims[size_t(k)];
            if (!may_hit(geometry, frustum, id)) continue;
            if (out.prims.size() == kMaxSubset) return give_up();
            out.prims.push_back(id);
        }
    }
    std::sort(out.prims.begin(), out.prims.end());
}

template void cull_to_frustum(const FlatGeometry<float>&, const TileFrustum&, PrimitiveSubset&);
template void cull_to_frustum(const FlatGeometry<double>&, const TileFrustum&, PrimitiveSubset&);

}  // namespace fh
