#include "render/flat_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fh {

namespace {

// A box computed in double and padded by a relative 1e-5, so that no
// rounding in the tracer's precision can put a hit outside it.
Aabb padded(Aabb b) {
    const double pad = 1e-5 * (glm::length(b.hi - b.lo) + std::max(glm::length(b.lo), glm::length(b.hi)));
    b.lo -= pad;
    b.hi += pad;
    return b;
}

// The BVH's input, by primitive id: the shapes' boxes, the planes' (empty:
// left out), then the triangles' (scene indices, in the flat order).
std::vector<Aabb> bounds_of(const Scene& scene, const std::vector<std::int32_t>& triangles) {
    std::vector<Aabb> boxes;
    boxes.reserve(scene.shapes.size() + scene.planes.size() + triangles.size());
    scene.shapes.each([&](const auto& s) { boxes.push_back(padded(s.bounds())); });
    boxes.resize(boxes.size() + scene.planes.size());
    for (const std::int32_t i : triangles) {
        const Triangle<double>& t = scene.triangles[size_t(i)];
        Aabb b;
        b.grow(t.v0);
        b.grow(t.v1);
        b.grow(t.v2);
        boxes.push_back(padded(b));
    }
    return boxes;
}

// The padded bounding sphere of a few triangles.
template <typename T>
BoundingSphere<T> bounding_sphere(const Scene& scene, const std::vector<std::int32_t>& triangles) {
    Aabb box;
    for (const std::int32_t i : triangles) {
        const Triangle<double>& t = scene.triangles[size_t(i)];
        box.grow(t.v0);
        box.grow(t.v1);
        box.grow(t.v2);
    }
    if (box.empty()) return {};
    const dvec3 center = box.center();
    double r = 0;
    for (const std::int32_t i : triangles) {
        const Triangle<double>& t = scene.triangles[size_t(i)];
        for (const dvec3& p : {t.v0, t.v1, t.v2}) r = std::max(r, glm::length(p - center));
    }
    r = r * (1 + 1e-4) + 1e-4 * max_abs_component(center) + 1e-30;
    return {Vec3<T>(center), T(r * r)};
}

bool smooth(const Scene& scene, size_t i) {
    if (scene.vertex_normals.empty()) return false;
    const auto& n = scene.vertex_normals[i];
    return n[0] != dvec3(0) || n[1] != dvec3(0) || n[2] != dvec3(0);
}

// Shapes, planes and the triangles listed (scene indices, in this order)
// with their surfaces, in primitive id order.
template <typename T>
void flatten(const Scene& scene, FlatGeometry<T>& g) {
    g.shapes = scene.shapes.in<T>();
    for (const auto& p : scene.planes) g.planes.push_back(p.template in<T>());
    g.ids = {int(g.shapes.size()), int(g.planes.size()), int(g.triangle_source.size())};
    g.surfaces.reserve(size_t(g.ids.end()));
    g.shapes.each([&](const auto& s) { g.surfaces.push_back(s.surface()); });
    for (const auto& p : g.planes) g.surfaces.push_back(p.surface());
    g.uvs.clear();
    for (const auto& c : scene.triangle_uvs)
        g.uvs.push_back({T(c[0].x), T(c[0].y), T(c[1].x), T(c[1].y), T(c[2].x), T(c[2].y)});
    g.tangents.clear();
    for (size_t i = 0; i < scene.triangle_tangents.size(); ++i) {
        const auto& t = scene.triangle_tangents[i];
        // The tangents' w is against the file's normals; shading turns those
        // to the side of the face's normal (SmoothTriangle). Where they point
        // against it, so do t and w: the turned normal comes out mirrored
        // through the face, as the face's normals are.
        const bool against = smooth(scene, i) && glm::dot(scene.vertex_normals[i][0] + scene.vertex_normals[i][1] +
                                                                  scene.vertex_normals[i][2],
                                                              scene.triangles[i].normal) < 0;
        const T sign = against ? T(-1) : T(1);
        g.tangents.push_back({sign * Vec3<T>(t[0]), sign * Vec3<T>(t[1]), sign * Vec3<T>(t[2]),
                              sign * (t[0].w + t[1].w + t[2].w < 0 ? T(-1) : T(1))});
    }
    g.colors.clear();
    for (const auto& c : scene.triangle_colors) g.colors.push_back({Color<T>(c[0]), Color<T>(c[1]), Color<T>(c[2])});
    g.alphas.clear();
    for (const auto& a : scene.triangle_alphas) g.alphas.push_back({T(a[0]), T(a[1]), T(a[2])});
    g.triangles.reserve(g.triangle_source.size());
    for (const std::int32_t i : g.triangle_source) {
        const Triangle<double>& t = scene.triangles[size_t(i)];
        g.triangles.push_back({Vec3<T>(t.v0), Vec3<T>(t.v1), Vec3<T>(t.v2), Vec3<T>(t.normal), t.material});
        g.surfaces.push_back(g.triangles.back().surface());
        if (!smooth(scene, size_t(i))) continue;
        const SmoothTriangle<T> st = SmoothTriangle<T>::make(t, scene.vertex_normals[size_t(i)]);
        // A triangle too small for T's range to solve for weights stays flat.
        if (!std::isfinite(st.inv_denominator)) continue;
        g.surfaces.back().smooth = int(g.smooth_triangles.size());
        g.smooth_triangles.push_back(st);
    }
}

// The triangles (and their surfaces and sources) renumbered in the order
// the BVH's leaves list them, so a leaf's triangles lie next to each other
// in memory: a walk reads them in runs instead of from anywhere in a
// million. (Small scenes keep the file's order.)
template <typename T>
void in_leaf_order(FlatGeometry<T>& g) {
    const PrimitiveIds& ids = g.ids;
    BigArray<Triangle<T>> triangles;
    BigArray<PrimitiveSurface<T>> surfaces(g.surfaces.begin(), g.surfaces.begin() + ids.first_triangle());
    std::vector<std::int32_t> source;
    triangles.reserve(g.triangles.size());
    source.reserve(g.triangles.size());
    for (std::int32_t& id : g.bvh.prims) {
        if (!ids.is_triangle(id)) continue;
        const size_t k = size_t(ids.triangle_index(id));
        triangles.push_back(g.triangles[k]);
        surfaces.push_back(g.surfaces[size_t(id)]);
        source.push_back(g.triangle_source[k]);
        id = ids.triangle(int(triangles.size()) - 1);
    }
    g.triangles.swap(triangles);
    g.surfaces.swap(surfaces);
    g.triangle_source.swap(source);
}

// The largest leaf the tracer in T asks the BVH for: as many triangles as
// one ray tests in one vector (TriangleBlock::kColumns), up to the walk's
// limit. Larger leaves mean fewer levels to walk, which is what a million
// triangles smaller than pixels wants, each leaf reached by one ray of a
// packet or two: in float with AVX-512, 15 instead of 8 took 1.3M
// triangles from 10.0-10.4 to 8.7-8.8 ms and the bunny from 4.3-4.4 to
// 4.1 ms. In double (8 lanes) 15 takes two vectors, and made 1,280
// triangles 12% slower.
template <typename T>
constexpr int kLeafTriangles = std::min(TriangleBlock<T>::kColumns, kMaxLeafSize);

// The walk's nodes and blocks over g.bvh (triangles already in leaf order).
template <typename T>
void prepare_walk(FlatGeometry<T>& g) {
    std::vector<std::int32_t> from;
    g.walk_nodes = walk_nodes_of<T>(g.bvh, g.ids, &from);
    std::vector<std::int32_t> walk_of(g.bvh.nodes.size(), -1);
    for (size_t k = 0; k < from.size(); ++k) walk_of[size_t(from[k])] = std::int32_t(k);
    g.wide = collapse(g.bvh, walk_of);
    g.blocks.clear();
    if constexpr (FlatGeometry<T>::kPackedRows) {
        // A vector of NaN past the last row: the one-ray test reads that far.
        g.packed_rows.assign(9 * g.triangles.size() + kLanes<T>, std::numeric_limits<T>::quiet_NaN());
        for (const WalkNode<T>& n : g.walk_nodes)
            if (n.leaf() && n.triangle_run())
                TriangleRows<T>::write(&g.triangles[size_t(n.first_triangle())], n.count(), n.count(),
                                       &g.packed_rows[9 * size_t(n.first_triangle())]);
        return;
    }
    for (const WalkNode<T>& n : g.walk_nodes)  // numbered in this order
        if (n.leaf() && n.triangle_run())
            g.blocks.push_back(TriangleBlock<T>::make(&g.triangles[size_t(n.first_triangle())], n.count()));
}

template <typename T>
void choose_small(const Scene& scene, FlatGeometry<T>& g) {
    g.small = g.bvh.prims.size() <= kMaxSubset;
    if (!g.small) return;
    g.few_triangles = bounding_sphere<T>(scene, g.triangle_source);
    g.everything.walk_bvh = false;
    g.everything.prims.assign(g.bvh.prims.begin(), g.bvh.prims.end());
    std::sort(g.everything.prims.begin(), g.everything.prims.end());
}

}  // namespace

template <typename T>
SmoothTriangle<T> SmoothTriangle<T>::make(const Triangle<double>& t, const std::array<dvec3, 3>& normals) {
    const dvec3 e1 = t.v1 - t.v0, e2 = t.v2 - t.v0;
    const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
    // Each vertex normal on the face normal's side (a file may wind its
    // faces against its normals); one nearly in the face's plane would let
    // the mix vanish, so it gives way to the face normal.
    auto oriented = [&](const dvec3& n) {
        const dvec3 u = unit_or_zero(n);
        const double along = glm::dot(u, t.normal);
        if (std::abs(along) < 1e-3) return t.normal;
        return along < 0 ? -u : u;
    };
    SmoothTriangle s;
    s.v0 = Vec3<T>(t.v0);
    s.e1 = Vec3<T>(e1);
    s.e2 = Vec3<T>(e2);
    s.d00 = T(d00);
    s.d01 = T(d01);
    s.d11 = T(d11);
    s.inv_denominator = T(1 / (d00 * d11 - d01 * d01));
    s.n0 = Vec3<T>(oriented(normals[0]));
    s.n1 = Vec3<T>(oriented(normals[1]));
    s.n2 = Vec3<T>(oriented(normals[2]));
    return s;
}

template <typename T>
FlatGeometry<T> FlatGeometry<T>::build(const Scene& scene, ThreadPool* pool) {
    FlatGeometry<T> g;
    // A triangle without area can never be hit: it stays out of the loop.
    for (size_t i = 0; i < scene.triangles.size(); ++i)
        if (!scene.triangles[i].degenerate()) g.triangle_source.push_back(std::int32_t(i));
    flatten(scene, g);
    g.bvh = build_bvh(bounds_of(scene, g.triangle_source), pool, kLeafTriangles<T>);
    choose_small(scene, g);
    if (!g.small) in_leaf_order(g);
    prepare_walk(g);
    return g;
}

template <typename T>
FlatGeometry<T> FlatGeometry<T>::refit(const Scene& moved, ThreadPool* pool) const {
    // The same primitives kept: as many triangles with area, and every one
    // this tree holds among them.
    size_t kept = 0;
    for (const auto& t : moved.triangles) kept += !t.degenerate();
    bool same = moved.shapes.size() == shapes.size() && moved.planes.size() == planes.size() &&
                kept == triangles.size();
    for (size_t k = 0; same && k < triangle_source.size(); ++k) {
        const size_t i = size_t(triangle_source[k]);
        same = i < moved.triangles.size() && !moved.triangles[i].degenerate();
    }
    if (!same) return build(moved, pool);
    FlatGeometry<T> g;
    g.triangle_source = triangle_source;
    flatten(moved, g);
    g.bvh = bvh;
    refit_bvh(g.bvh, bounds_of(moved, g.triangle_source));
    prepare_walk(g);
    choose_small(moved, g);
    return g;
}

template <typename T>
SurfacePoint<T> FlatGeometry<T>::surface(const Ray<T>& ray, const Hit<T>& hit) const {
    const RayPacket<T> packet = RayPacket<T>::splat(ray);
    Vec3Lanes<T> point, normal, shading;
    project(hit.prim, packet.at(splat(hit.t)), point, normal, shading);
    const LaneInts<T> flip = dot(normal, packet.direction) > T(0);
    normal = select(flip, -normal, normal);
    shading = select(flip, -shading, shading);
    return {point.lane(0), normal.lane(0), shading.lane(0), surfaces[size_t(hit.prim)].material};
}

template struct FlatGeometry<float>;
template struct FlatGeometry<double>;

}  // namespace fh
