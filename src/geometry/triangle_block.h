// A BVH leaf's triangles, column by column: row r holds coordinate r % 3 of
// vertex r / 3 of every triangle, so one load takes that coordinate of
// them all. Two ways to test them, the same formula (triangle.h) either way:
//  - a packet of rays against one column, each lane a ray;
//  - one ray against every column, each lane a triangle: what a leaf that
//    only one or two of a packet's rays reach wants. Over triangles smaller
//    than a pixel the rays of a packet part ways near the leaves, and most
//    leaves are reached by a single ray; a packet would test each triangle
//    in turn, for one ray, where this tests them all at once.
// Unused columns and triangles without area hold NaN, which never hits.
#pragma once

#include <limits>

#include "geometry/triangle.h"

namespace fh {

// A leaf's triangles as rows of `stride` values (row r at rows + r * stride):
// a leaf's rows packed end to end (FlatGeometry::packed_rows, in float).
// Its two tests are TriangleBlock's, written out again: routed through one
// function for both (taking where a row is), both tracers compiled
// differently and the float frames came out 3-4% slower than with the
// copies (interleaved rounds).
template <typename T>
struct TriangleRows {
    const T* rows;
    int stride;

    // Writes count triangles as rows of `stride` values from out on
    // (columns past count are left as they are).
    static void write(const Triangle<T>* triangles, int count, int stride, T* out) {
        for (int j = 0; j < count; ++j) {
            const Triangle<T>& t = triangles[j];
            const Vec3<T> v[3] = {t.v0, t.v1, t.v2};
            for (int r = 0; r < 9; ++r)
                out[r * stride + j] = t.degenerate() ? std::numeric_limits<T>::quiet_NaN() : v[r / 3][r % 3];
        }
    }

    FH_HOT_INLINE T at(int r, int j) const { return rows[r * stride + j]; }

    // A packet against column j: each ray's t in (t_min, t_max), or infinity.
    FH_HOT_INLINE Lanes<T> intersect(const RayBasis<T>& rays, int j, T t_min, const Lanes<T>& t_max) const {
        const Vec3Lanes<T>& o = rays.ray.origin;
        const Vec3<T> v0{at(0, j), at(1, j), at(2, j)};
        const Vec3<T> v1{at(3, j), at(4, j), at(5, j)};
        const Vec3<T> v2{at(6, j), at(7, j), at(8, j)};
        return watertight_distance<T>(v0 - o, v1 - o, v2 - o, rays.ray.direction, rays.e, rays.g, t_min, t_max);
    }

    // Ray `lane` of a packet against columns [j0, j0 + kLanes) of the first
    // `count`: each column's t in (t_min, t_max), or infinity. (A vector
    // wider than a row reads on into the next, or past the last row, which
    // the storage must allow; those lanes are masked.) t_max: that ray's in
    // every lane.
    FH_HOT_INLINE Lanes<T> intersect(const RayBasis<T>& rays, int lane, int j0, int count, T t_min,
                                     const Lanes<T>& t_max) const {
        auto row = [&](int r) FH_HOT_LAMBDA { return load(rows + r * stride + j0); };
        const Vec3Lanes<T> o = rays.ray.origin.splat_lane(lane);
        const Vec3Lanes<T> v0{row(0), row(1), row(2)}, v1{row(3), row(4), row(5)}, v2{row(6), row(7), row(8)};
        const Lanes<T> limit = select(first_lanes<T>(count - j0), t_max, splat(T(0)));
        return watertight_distance<T>(v0 - o, v1 - o, v2 - o, rays.ray.direction.splat_lane(lane),
                                      rays.e.splat_lane(lane), rays.g.splat_lane(lane), t_min, limit);
    }
};

template <typename T>
struct alignas(64) TriangleBlock {
    // As many columns as one vector holds (16 floats with AVX-512), at least 8.
    static constexpr int kColumns = kLanes<T> > 8 ? 16 : 8;
    T rows[9][kColumns];

    static TriangleBlock make(const Triangle<T>* triangles, int count) {
        TriangleBlock b;
        for (auto& row : b.rows)
            for (T& x : row) x = std::numeric_limits<T>::quiet_NaN();
        TriangleRows<T>::write(triangles, count, kColumns, &b.rows[0][0]);
        return b;
    }

    // A packet against column j: each ray's t in (t_min, t_max), or infinity.
    FH_HOT_INLINE Lanes<T> intersect(const RayBasis<T>& rays, int j, T t_min, const Lanes<T>& t_max) const {
        const Vec3Lanes<T>& o = rays.ray.origin;
        const Vec3<T> v0{rows[0][j], rows[1][j], rows[2][j]};
        const Vec3<T> v1{rows[3][j], rows[4][j], rows[5][j]};
        const Vec3<T> v2{rows[6][j], rows[7][j], rows[8][j]};
        return watertight_distance<T>(v0 - o, v1 - o, v2 - o, rays.ray.direction, rays.e, rays.g, t_min, t_max);
    }

    // Ray `lane` of a packet against columns [j0, j0 + kLanes) of the first
    // `count`: each column's t in (t_min, t_max), or infinity. (A vector
    // wider than a row reads on into the next; those lanes are masked.)
    // t_max: that ray's in every lane.
    FH_HOT_INLINE Lanes<T> intersect(const RayBasis<T>& rays, int lane, int j0, int count, T t_min,
                                     const Lanes<T>& t_max) const {
        auto row = [&](int r) FH_HOT_LAMBDA { return load(&rows[r][j0]); };
        const Vec3Lanes<T> o = rays.ray.origin.splat_lane(lane);
        const Vec3Lanes<T> v0{row(0), row(1), row(2)}, v1{row(3), row(4), row(5)}, v2{row(6), row(7), row(8)};
        const Lanes<T> limit = select(first_lanes<T>(count - j0), t_max, splat(T(0)));
        return watertight_distance<T>(v0 - o, v1 - o, v2 - o, rays.ray.direction.splat_lane(lane),
                                      rays.e.splat_lane(lane), rays.g.splat_lane(lane), t_min, limit);
    }
};

// A vector load of the last row stays inside the block.
static_assert(sizeof(TriangleBlock<float>) >= sizeof(float) * (8 * TriangleBlock<float>::kColumns + kLanes<float>));
static_assert(sizeof(TriangleBlock<double>) >=
              sizeof(double) * (8 * TriangleBlock<double>::kColumns + kLanes<double>));

}  // namespace fh
