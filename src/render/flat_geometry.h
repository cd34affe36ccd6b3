// The shapes as the tracer reads them: contiguous arrays per shape kind in
// the tracer's scalar type, the BVH over them, and per primitive what shading
// needs to turn a hit into a point and a normal. Built once per scene and
// shared by every frame whose geometry does not move; a frame whose objects
// move gets a refitted copy (same tree, new boxes). Nothing here knows about
// lights or materials beyond a material's index (render/flat_scene.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "core/hit.h"
#include "geometry/shapes.h"
#include "geometry/triangle_block.h"
#include "render/bvh_traversal.h"
#include "render/primitive_ids.h"
#include "render/wide_bvh.h"
#include "scene/texture.h"
#include "scene/scene.h"

namespace fh {

class ThreadPool;

// The bounded primitives a tile's camera rays can hit (render/tile_culling.h),
// by id (render/primitive_ids.h), in increasing order. A short list is tested one by one, which for a few primitives is
// faster than walking the BVH; past kMaxSubset the walk is used instead.
struct PrimitiveSubset {
    std::vector<int> prims;
    bool walk_bvh = true;  // too many (or not culled): walk the BVH
};
inline constexpr size_t kMaxSubset = 16;

inline constexpr int kNoHit = -1;  // no primitive id

// A padded sphere around all of a small scene's triangles (FlatGeometry::
// few_triangles). A ray that misses it skips them all, with no division and
// no walk: for a scene of a few primitives -- the report's has seven --
// that is faster than any BVH.
template <typename T>
struct BoundingSphere {
    Vec3<T> center{0};
    T radius2 = 0;  // padded so rounding never culls a real hit

    // Per lane: the ray meets the sphere ahead of its origin (or starts
    // inside it). A plain test is enough for a padded bound; the robust one
    // of Sphere costs more. The far root b + sqrt(disc) is ahead when b > 0
    // or disc > b^2, which needs no square root.
    FH_HOT_INLINE LaneInts<T> reaches(const RayPacket<T>& ray) const {
        const Vec3Lanes<T> f = ray.origin - center;
        const Lanes<T> b = -dot(f, ray.direction);
        const Vec3Lanes<T> closest = f + b * ray.direction;
        const Lanes<T> disc = radius2 - dot(closest, closest);
        return (disc >= T(0)) & ((b > T(0)) | (disc > b * b));
    }
};

// The barycentric weights b1, b2 of points v0 + d over a triangle's edges
// e1, e2 (d00, d01, d11: their dot products; inv_denominator: 1 / (d00 d11
// - d01^2)), clamped to the triangle: a point rounding puts just outside an
// edge gets that edge's weights, not extrapolated ones.
template <typename T>
FH_HOT_INLINE void clamped_weights(const Vec3Lanes<T>& d, const Vec3<T>& e1, const Vec3<T>& e2, T d00, T d01, T d11,
                                   T inv_denominator, Lanes<T>& b1, Lanes<T>& b2) {
    const Lanes<T> d20 = dot(d, e1), d21 = dot(d, e2);
    const Lanes<T> zero = splat(T(0)), one = splat(T(1));
    b1 = max(zero, min(one, (d11 * d20 - d01 * d21) * inv_denominator));
    b2 = max(zero, min(one, (d00 * d21 - d01 * d20) * inv_denominator));
    const Lanes<T> over = max(one, b1 + b2);  // b0 = 1 - b1 - b2 >= 0
    b1 = b1 / over;
    b2 = b2 / over;
}

// A smooth-shaded triangle's vertex normals, with what turns a point of the
// triangle into barycentric weights: p - v0 = b1 e1 + b2 e2, solved by the
// normal equations (Ericson, Real-Time Collision Detection, 3.4).
template <typename T>
struct SmoothTriangle {
    Vec3<T> v0{0}, e1{0}, e2{0};
    T d00 = 0, d01 = 0, d11 = 0, inv_denominator = 0;
    Vec3<T> n0{0}, n1{0}, n2{0};  // unit, on the side of the face normal

    static SmoothTriangle make(const Triangle<double>& t, const std::array<dvec3, 3>& normals);

    // At points p of the triangle: the vertex normals mixed by p's weights,
    // unit. Weights are clamped to the triangle, so a point rounding puts
    // just outside an edge gets that edge's normal, not an extrapolated one.
    FH_HOT_INLINE Vec3Lanes<T> normal_at(const Vec3Lanes<T>& p) const {
        Lanes<T> b1, b2;
        clamped_weights(p - v0, e1, e2, d00, d01, d11, inv_denominator, b1, b2);
        return normalize((T(1) - b1 - b2) * n0 + b1 * n1 + b2 * n2);
    }
};

// A triangle's texture coordinates: (u, v) at v0, v1 and v2.
template <typename T>
struct TriangleUvs {
    T u0, v0, u1, v1, u2, v2;
};

// Where points lie on a triangle, for what its vertices carry: the
// weights b1, b2 of v1 and v2 and, where its mesh has texture coordinates,
// (u, v) there (FlatGeometry::point_on).
// footprint: each pixel's there in (u, v) units, where a texture may be
// read from its mipmaps (render/texture_footprint.h); by default a point.
template <typename T>
struct TrianglePoint {
    Lanes<T> b1, b2, u, v;
    UvFootprint<T> footprint;
};

// A triangle's edges from v0 in space and in its texture coordinates, and
// the determinant of the latter (twice its signed area in the image).
template <typename T>
struct UvEdges {
    Vec3<T> e1, e2;
    T du1, dv1, du2, dv2, det;
};

// A triangle's tangents at v0, v1 and v2 (a glTF TANGENT's xyz, or those
// made for its corners: scene/mesh_tangents.h), and the bitangent's sign w
// (the three's, as a triangle's corners share it).
template <typename T>
struct TriangleTangents {
    Vec3<T> t0, t1, t2;
    T w;
};

// A triangle's vertex colours (each channel in [0, 1]) at v0, v1 and v2.
template <typename T>
struct TriangleColors {
    Color<T> c0, c1, c2;
};
template <typename T>
struct TriangleAlphas {
    T a0, a1, a2;
};

// The normal turned to face the ray (report 8.4).
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> facing(const Vec3Lanes<T>& normal, const Vec3Lanes<T>& direction) {
    return select(dot(normal, direction) > T(0), -normal, normal);
}

// One hit's point and normals (tests, the viewer).
template <typename T>
struct SurfacePoint {
    Vec3<T> point{0};
    Vec3<T> normal{0};   // the geometric normal, facing the ray
    Vec3<T> shading{0};  // what lighting uses: the smooth normal, else `normal`
    int material = -1;
};

template <typename T>
struct FlatGeometry {
    BoundedShapes<T> shapes;
    std::vector<Plane<T>> planes;
    BigArray<Triangle<T>> triangles;
    PrimitiveIds ids;  // of shapes, planes and triangles, in that order
    // Over every primitive but the planes, by id.
    Bvh bvh;
    BigArray<WalkNode<T>> walk_nodes;  // bvh.nodes as the walk reads them
    WideBvh wide;                      // the same tree eight children a node, for rays alone
    // The triangles of the leaves that hold only triangles, a block a leaf
    // (in double; float packs them in packed_rows below).
    BigArray<TriangleBlock<T>> blocks;
    // At most kMaxSubset shapes and triangles: no BVH walk, every shape
    // tested, the triangles behind one bounding sphere, all in id order.
    bool small = false;
    BoundingSphere<T> few_triangles;
    // A small scene's every shape and triangle, as a list in id order
    // (render/packet_intersect.h tests it one by one); larger: walk_bvh.
    PrimitiveSubset everything;
    BigArray<PrimitiveSurface<T>> surfaces;  // by primitive id
    BigArray<SmoothTriangle<T>> smooth_triangles;
    // triangles[k] is the Scene's triangles[triangle_source[k]]: a refit
    // reads the moved triangles in the same order.
    std::vector<std::int32_t> triangle_source;
    // In float, the leaves' triangles (those `blocks` holds in double) with
    // their rows packed: a leaf of count triangles from triangle a on has
    // row r at 9 a + r count, so no column is left unused (a float block
    // has 16, a leaf 10.5 on average). 3-4% faster in float from 1,280 to
    // 1.3 million triangles. Double keeps blocks, whose rows are cache
    // lines: packed, they straddle lines, and the bunny was 3% slower.
    // (Last in the struct, so that double's code, which never reads it,
    // stays as it was.)
    BigArray<T> packed_rows;
    // An instance's textured mesh: each triangle's texture coordinates, by
    // its index in the Scene (triangle_source's values); else empty.
    BigArray<TriangleUvs<T>> uvs;
    // An instance's mesh with tangents (given or made): each triangle's,
    // the same way; else empty.
    BigArray<TriangleTangents<T>> tangents;
    // An instance's mesh with vertex colours: each triangle's, the same way.
    BigArray<TriangleColors<T>> colors;
    // An instance's mesh with vertex alphas (a glTF COLOR_0's): the same.
    BigArray<TriangleAlphas<T>> alphas;
    static constexpr bool kPackedRows = std::is_same_v<T, float>;

    // pool: the BVH is built on it (nullptr: on the calling thread).
    static FlatGeometry build(const Scene& scene, ThreadPool* pool = nullptr);

    // The same tree over `moved`, a scene with the same primitives in new
    // places (a movie's frame): only boxes and shapes are recomputed. When
    // that is not possible -- a primitive appeared or vanished, a triangle
    // lost its area -- the geometry is built anew instead.
    FlatGeometry refit(const Scene& moved, ThreadPool* pool = nullptr) const;

    // A leaf's packed rows (kPackedRows; n: a run of triangles).
    FH_HOT_INLINE TriangleRows<T> packed_rows_of(const WalkNode<T>& n) const {
        return {&packed_rows[9 * size_t(n.first_triangle())], n.count()};
    }

    const std::vector<Sphere<T>>& spheres() const { return shapes.template of<Sphere>(); }

    // Each ray's t on primitive `id`, a shape or a triangle (not a plane).
    FH_HOT_INLINE Lanes<T> intersect(int id, const RayBasis<T>& basis, T t_min, const Lanes<T>& t_max) const {
        if (ids.is_triangle(id)) return triangles[size_t(ids.triangle_index(id))].intersect(basis, t_min, t_max);
        return shapes.visit(size_t(id), [&](const auto& s) FH_HOT_LAMBDA {
            return s.intersect(basis.ray, t_min, t_max);
        });
    }

    // For the lanes of points p on primitive `prim`: the projected point, its
    // geometric normal and its shading normal (both outward, not yet facing
    // the ray).
    FH_HOT_INLINE void project(int prim, const Vec3Lanes<T>& p, Vec3Lanes<T>& point, Vec3Lanes<T>& normal,
                               Vec3Lanes<T>& shading) const {
        const PrimitiveSurface<T>& s = surfaces[size_t(prim)];
        s.project(p, point, normal);
        shading = s.smooth < 0 ? normal : smooth_triangles[size_t(s.smooth)].normal_at(point);
    }

    // The weights b1, b2 of v1 and v2 at points p of triangle `prim`
    // (clamped to the triangle), for what its vertices carry.
    FH_HOT_INLINE void weights_at(int prim, const Vec3Lanes<T>& p, Lanes<T>& b1, Lanes<T>& b2) const {
        const Triangle<T>& t = triangles[size_t(ids.triangle_index(prim))];
        const Vec3<T> e1 = t.v1 - t.v0, e2 = t.v2 - t.v0;
        const T d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
        clamped_weights(p - Vec3Lanes<T>::splat(t.v0), e1, e2, d00, d01, d11, T(1) / (d00 * d11 - d01 * d01), b1, b2);
    }

    // Points p of triangle `prim`: their weights, and their coordinates
    // where the mesh has some (else u, v are 0).
    FH_HOT_INLINE TrianglePoint<T> point_on(int prim, const Vec3Lanes<T>& p) const {
        TrianglePoint<T> at{};
        weights_at(prim, p, at.b1, at.b2);
        if (!uvs.empty()) uv_at(prim, at.b1, at.b2, at.u, at.v);
        return at;
    }

    // Texture coordinates (u, v) of triangle `prim` at weights b1, b2 (uvs not empty).
    FH_HOT_INLINE void uv_at(int prim, const Lanes<T>& b1, const Lanes<T>& b2, Lanes<T>& u, Lanes<T>& v) const {
        const TriangleUvs<T>& c = uvs[size_t(triangle_source[size_t(ids.triangle_index(prim))])];
        u = c.u0 + b1 * (c.u1 - c.u0) + b2 * (c.u2 - c.u0);
        v = c.v0 + b1 * (c.v1 - c.v0) + b2 * (c.v2 - c.v0);
    }

    // Triangle `prim`'s direction of increasing u (dP/du up to a positive
    // factor), and the sign w that turns n x dP/du into the image's up,
    // -dP/dv (glTF's v runs down the image), n its face's normal: -1 where
    // its coordinates are mirrored (uvs not empty). False where its
    // coordinates do not span it (collinear in the image).
    bool tangent_of(int prim, Vec3<T>& du, T& w) const {
        const UvEdges<T> c = uv_edges(prim);
        if (!(c.det != 0) || !std::isfinite(c.det)) return false;
        // dP/du = (dv2 e1 - dv1 e2) / det, dP/dv = (du1 e2 - du2 e1) / det.
        const Vec3<T> along = c.dv2 * c.e1 - c.dv1 * c.e2, dv = c.du1 * c.e2 - c.du2 * c.e1;  // times det
        du = (c.det > 0 ? T(1) : T(-1)) * along;
        w = glm::dot(glm::cross(glm::cross(c.e1, c.e2), along), dv) > 0 ? T(-1) : T(1);  // the sign is det^2's
        return glm::dot(du, du) > 0;
    }

    // Triangle `prim`'s edges and coordinate differences (uvs not empty).
    UvEdges<T> uv_edges(int prim) const {
        const Triangle<T>& t = triangles[size_t(ids.triangle_index(prim))];
        const TriangleUvs<T>& c = uvs[size_t(triangle_source[size_t(ids.triangle_index(prim))])];
        const T du1 = c.u1 - c.u0, dv1 = c.v1 - c.v0, du2 = c.u2 - c.u0, dv2 = c.v2 - c.v0;
        return {t.v1 - t.v0, t.v2 - t.v0, du1, dv1, du2, dv2, du1 * dv2 - du2 * dv1};
    }

    // The tangents of triangle `prim` (tangents not empty).
    const TriangleTangents<T>& tangents_of(int prim) const {
        return tangents[size_t(triangle_source[size_t(ids.triangle_index(prim))])];
    }

    // The vertex colour of triangle `prim` at weights b1, b2 (colors not empty).
    FH_HOT_INLINE ColorLanes<T> color_at(int prim, const Lanes<T>& b1, const Lanes<T>& b2) const {
        const TriangleColors<T>& c = colors[size_t(triangle_source[size_t(ids.triangle_index(prim))])];
        auto channel = [&](T x0, T x1, T x2) FH_HOT_LAMBDA { return x0 + b1 * (x1 - x0) + b2 * (x2 - x0); };
        return {channel(c.c0.x, c.c1.x, c.c2.x), channel(c.c0.y, c.c1.y, c.c2.y), channel(c.c0.z, c.c1.z, c.c2.z)};
    }

    // The vertex alpha of triangle `prim` at weights b1, b2 (alphas not empty).
    FH_HOT_INLINE Lanes<T> alpha_at(int prim, const Lanes<T>& b1, const Lanes<T>& b2) const {
        const TriangleAlphas<T>& a = alphas[size_t(triangle_source[size_t(ids.triangle_index(prim))])];
        return a.a0 + b1 * (a.a1 - a.a0) + b2 * (a.a2 - a.a0);
    }

    // Point, normals facing the ray, and material of one hit (tests): the
    // formula shading uses, on a packet of one.
    SurfacePoint<T> surface(const Ray<T>& ray, const Hit<T>& hit) const;
};

extern template struct FlatGeometry<float>;
extern template struct FlatGeometry<double>;

}  // namespace fh
