// Which primitives a tile's camera rays can hit. The camera rays through a
// rectangle of the image lie inside the frustum of its four side planes: a
// pyramid from the eye (perspective) or a prism (orthographic). A box, a
// triangle or a sphere wholly outside one of them (by a margin) is hit by
// none of the tile's rays, so the tile's first hits skip it: a few plane
// tests per BVH node per tile instead of a test per packet. Planes,
// infinite, are always tested.
#pragma once

#include <vector>

#include "render/flat_geometry.h"
#include "scene/camera.h"

namespace fh {

// A side plane of a frustum: a point of it and its unit normal, pointing inside.
struct FrustumSide {
    dvec3 point, normal;
};

class TileFrustum {
public:
    // The frustum of the pixels [x0, x1) x [y0, y1) (continuous pixel
    // coordinates, as CameraRays takes them), from its corner rays.
    TileFrustum(const CameraRays<double>& camera, double x0, double x1, double y0, double y1);
    TileFrustum(const FrustumSide& left, const FrustumSide& right, const FrustumSide& top,
                const FrustumSide& bottom)
        : sides_{left, right, top, bottom} {}

    // Each test keeps anything within a margin outside a side: a relative
    // 1e-4 of its distance from the side's point, far above the rounding
    // of rays in float.

    // False only if no ray of the frustum can meet the sphere.
    bool may_hit(const dvec3& center, double radius) const;
    template <typename T>
    bool may_hit(const Sphere<T>& s) const { return may_hit(dvec3(s.center), double(s.radius)); }
    // Any other bounded shape: by its box.
    template <typename Shape>
    bool may_hit(const Shape& s) const {
        const Aabb b = s.bounds();
        return overlap(b.lo, b.hi) != Overlap::outside;
    }
    // False only if no ray of the frustum can meet the triangle.
    bool may_hit(const dvec3& a, const dvec3& b, const dvec3& c) const;

    // Where a box lies: outside (no ray meets it), inside (wholly within
    // every side, margin included: each of its primitives is kept) or across.
    enum class Overlap { outside, across, inside };
    Overlap overlap(const dvec3& lo, const dvec3& hi) const;

private:
    FrustumSide sides_[4];
};

// The side planes of every tile of an image, computed once a frame: the side
// two neighbouring tiles share is the plane of the camera rays through that
// line of the image, the same for both.
class TileSides {
public:
    TileSides(const CameraRays<double>& camera, int width, int height, int tile_size);

    // The tile [x0, x1) x [y0, y1): each bound a multiple of tile_size or
    // the image's edge.
    TileFrustum frustum(int x0, int x1, int y0, int y1) const;

private:
    int line(int coordinate, int size) const;  // index of the line at a bound
    int tile_size_;
    int width_, height_;
    std::vector<FrustumSide> columns_, rows_;  // facing increasing x, y
};

// Above this many primitives a BVH is not walked with a tile's frustum.
// Measured on icospheres (bench_scaling, float, 2 threads): culling made
// 320 triangles 2% faster and 1,280 1% slower.
inline constexpr int kMaxCulledPrimitives = 1024;

// The shapes and triangles of `geometry` the frustum may hit, by id, into `out`: found
// by walking the BVH with the frustum; more than kMaxSubset of them (or a
// tree of more than kMaxCulledPrimitives whose root box the frustum meets)
// and `out` says to walk the BVH per packet instead.
template <typename T>
void cull_to_frustum(const FlatGeometry<T>& geometry, const TileFrustum& frustum, PrimitiveSubset& out);

}  // namespace fh
