// A tile's frustum (render/tile_culling.h) never drops a sphere, triangle or
// box that one of the tile's camera rays hits, and does drop the ones well
// outside it -- built from the tile's corner rays or from the frame's shared
// sides alike; and culling a scene lists exactly the triangles the frustum
// keeps, or gives up only when they are too many.
#include <gtest/gtest.h>

#include <random>

#include "geometry/icosphere.h"
#include "render/tile_culling.h"
#include "robustness/robust_util.h"

namespace fh {
namespace {

Camera camera_of(Projection projection, const dvec3& eye) {
    Camera c;
    c.projection = projection;
    c.width = 800;
    c.height = 600;
    c.view_point = eye;
    c.look_at = -eye;  // toward the origin
    return c;
}

// Does some ray through the tile [x0, x1) x [y0, y1) hit the sphere? Rays on
// a fine grid, edges and corners included.
bool some_ray_hits(const CameraRays<double>& rays, double x0, double x1, double y0, double y1,
                   const Sphere<double>& s) {
    for (int i = 0; i <= 32; ++i)
        for (int j = 0; j <= 32; ++j)
            if (s.intersect(rays.generate(x0 + (x1 - x0) * i / 32, y0 + (y1 - y0) * j / 32), 0,
                            kInfinity<double>) < kInfinity<double>)
                return true;
    return false;
}

TEST(TileCulling, KeepsEverySphereATilesRayHits) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int hit = 0, missed = 0;
    for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
        for (int trial = 0; trial < 300; ++trial) {
            const Camera cam = camera_of(projection, dvec3(20 * u(rng), -30 + 5 * u(rng), 15 + 10 * u(rng)));
            const CameraRays<double> rays(cam);
            // A tile of the grid, so that the frame's shared sides make it too.
            const int x0 = 16 * int(25 + 18 * u(rng)), y0 = 16 * int(18 + 12 * u(rng));
            const TileFrustum corners(rays, x0, x0 + 16, y0, y0 + 16);
            const TileFrustum shared = TileSides(rays, cam.width, cam.height, 16).frustum(x0, x0 + 16, y0, y0 + 16);
            // A sphere centred near a corner ray of the tile, at a random
            // depth, of a radius that makes it graze the tile or just miss.
            const Ray<double> corner = rays.generate(x0 + (u(rng) > 0 ? 16 : 0), y0 + (u(rng) > 0 ? 16 : 0));
            const double depth = 5 + 40 * (u(rng) + 1);
            const dvec3 off = glm::normalize(glm::cross(corner.direction, dvec3(u(rng), u(rng), u(rng))));
            const double radius = 0.05 + 2 * (u(rng) + 1);
            const Sphere<double> s{corner.at(depth) + (radius * (1 + 0.02 * u(rng))) * off, radius, 0};
            const bool hits = some_ray_hits(rays, x0, x0 + 16, y0, y0 + 16, s);
            if (hits) {
                ++hit;
                for (const TileFrustum* frustum : {&corners, &shared})
                    EXPECT_TRUE(frustum->may_hit(s.center, s.radius))
                        << "trial " << trial << ": a sphere the tile's rays hit was culled";
            } else {
                ++missed;
            }
        }
    }
    // Both kinds occur: the spheres graze the tile's corner rays from both
    // sides. (Near a corner the side planes are conservative: a sphere that
    // misses may still be kept, never the other way round.)
    EXPECT_GT(hit, 100);
    EXPECT_GT(missed, 50);
}

// Both constructions of the tile [384, 400) x [288, 304) of an 800x600 image.
std::vector<TileFrustum> frustums_of(const CameraRays<double>& rays) {
    return {TileFrustum(rays, 384, 400, 288, 304), TileSides(rays, 800, 600, 16).frustum(384, 400, 288, 304)};
}

TEST(TileCulling, DropsSpheresWellOutsideTheTile) {
    for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
        const CameraRays<double> rays(camera_of(projection, {0, -30, 20}));
        for (const TileFrustum& frustum : frustums_of(rays)) {
            const Ray<double> centre = rays.generate(392, 296);
            EXPECT_TRUE(frustum.may_hit(centre.at(20), 0.1));
            const Ray<double> left = rays.generate(100, 296);
            EXPECT_FALSE(frustum.may_hit(left.at(20), 1.0)) << int(projection);
            // Behind the eye (perspective): outside the pyramid.
            if (projection == Projection::perspective) EXPECT_FALSE(frustum.may_hit(centre.at(-20), 0.01));
        }
    }
}

// Does a ray cross the triangle (Moller-Trumbore, plain double: a test's
// ground truth, not the tracer's test)?
bool crosses(const Ray<double>& r, const dvec3& a, const dvec3& b, const dvec3& c) {
    const dvec3 e1 = b - a, e2 = c - a, p = glm::cross(r.direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-300) return false;
    const dvec3 s = r.origin - a, q = glm::cross(s, e1);
    const double u = glm::dot(s, p) / det, v = glm::dot(r.direction, q) / det, t = glm::dot(e2, q) / det;
    return u >= 0 && v >= 0 && u + v <= 1 && t > 0;
}

// Does the ray meet the box ahead of its origin (slab test)?
bool crosses(const Ray<double>& r, const dvec3& lo, const dvec3& hi) {
    double near = 0, far = kInfinity<double>;
    for (int k = 0; k < 3; ++k) {
        const double t0 = (lo[k] - r.origin[k]) / r.direction[k], t1 = (hi[k] - r.origin[k]) / r.direction[k];
        near = std::max(near, std::min(t0, t1));
        far = std::min(far, std::max(t0, t1));
    }
    return near <= far;
}

TEST(TileCulling, KeepsEveryTriangleAndBoxATilesRayHits) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    int hit = 0, culled = 0;
    for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
        const CameraRays<double> rays(camera_of(projection, {3, -30, 18}));
        for (const TileFrustum& frustum : frustums_of(rays)) {
            for (int trial = 0; trial < 400; ++trial) {
                // A triangle with a vertex near a corner ray, the others up
                // to a few units away; a box around a point near one.
                const Ray<double> corner = rays.generate(trial % 2 ? 400 : 384, trial % 4 < 2 ? 304 : 288);
                const dvec3 a = corner.at(10 + 30 * (u(rng) + 1)) + 0.3 * dvec3(u(rng), u(rng), u(rng));
                const dvec3 b = a + 3.0 * dvec3(u(rng), u(rng), u(rng)), c = a + 3.0 * dvec3(u(rng), u(rng), u(rng));
                const dvec3 half = 0.2 * dvec3(u(rng) + 1, u(rng) + 1, u(rng) + 1);
                bool triangle_hit = false, box_hit = false;
                for (int i = 0; i <= 32; ++i)
                    for (int j = 0; j <= 32; ++j) {
                        const Ray<double> r = rays.generate(384 + i * 0.5, 288 + j * 0.5);
                        triangle_hit = triangle_hit || crosses(r, a, b, c);
                        box_hit = box_hit || crosses(r, a - half, a + half);
                    }
                const bool triangle_kept = frustum.may_hit(a, b, c);
                const bool box_kept = frustum.overlap(a - half, a + half) != TileFrustum::Overlap::outside;
                if (triangle_hit)
                    EXPECT_TRUE(triangle_kept) << "trial " << trial << ": a triangle the tile's rays hit was culled";
                if (box_hit) EXPECT_TRUE(box_kept) << "trial " << trial << ": a box the tile's rays hit was culled";
                hit += triangle_hit + box_hit;
                culled += !triangle_kept + !box_kept;
            }
            // A triangle over the whole tile, each vertex outside a different side.
            EXPECT_TRUE(frustum.may_hit(rays.generate(100, 296).at(20), rays.generate(700, 200).at(20),
                                        rays.generate(400, 580).at(20)));
            // Boxes: one around a point of the centre ray, one across the
            // tile's left side, one far to the left.
            const dvec3 centre = rays.generate(392, 296).at(20), edge = rays.generate(384, 296).at(20);
            const dvec3 tiny(1e-3);
            EXPECT_EQ(frustum.overlap(centre - tiny, centre + tiny), TileFrustum::Overlap::inside);
            EXPECT_EQ(frustum.overlap(edge - tiny, edge + tiny), TileFrustum::Overlap::across);
            const dvec3 left = rays.generate(100, 296).at(20);
            EXPECT_EQ(frustum.overlap(left - tiny, left + tiny), TileFrustum::Overlap::outside);
        }
    }
    EXPECT_GT(hit, 800);     // both kinds occur
    EXPECT_GT(culled, 400);
}

// Culling a scene over every tile of an image lists exactly the triangles
// the frustum keeps, one by one; it gives up (walk the BVH) only when they
// are more than kMaxSubset -- including where it gives up early, at a node
// wholly inside the frustum. A tree of more than kMaxCulledPrimitives is
// walked wherever the frustum meets its root box, and skipped elsewhere.
template <typename T>
void check_culling(int subdivisions, int* gave_up, int* listed) {
    Scene s;
    robust::add_material(s, "m", robust::material(dvec3(200), 0.2, 0.8, 0, 1));
    s.triangles = icosphere(subdivisions, 3.0, 0);
    const auto g = FlatGeometry<T>::build(s);
    Camera cam;
    cam.width = cam.height = 320;
    cam.view_point = {0, -12, 6};
    cam.look_at = {0, 12, -6};
    cam.projection_distance = 30;  // the sphere fills most of the image
    const CameraRays<double> rays(cam);
    const TileSides sides(rays, cam.width, cam.height, 16);
    PrimitiveSubset out;
    for (int y0 = 0; y0 < cam.height; y0 += 16)
        for (int x0 = 0; x0 < cam.width; x0 += 16) {
            const TileFrustum frustum = sides.frustum(x0, x0 + 16, y0, y0 + 16);
            std::vector<int> kept;
            for (int i = 0; i < int(g.triangles.size()); ++i) {
                const Triangle<T>& t = g.triangles[size_t(i)];
                if (frustum.may_hit(dvec3(t.v0), dvec3(t.v1), dvec3(t.v2))) kept.push_back(i);
            }
            cull_to_frustum(g, frustum, out);
            if (g.bvh.nodes[0].below > kMaxCulledPrimitives) {
                // A big tree: only its root box is tested.
                const BvhNode& root = g.bvh.nodes[0];
                const bool meets = frustum.overlap(dvec3(root.lo[0], root.lo[1], root.lo[2]),
                                                   dvec3(root.hi[0], root.hi[1], root.hi[2])) !=
                                   TileFrustum::Overlap::outside;
                EXPECT_EQ(out.walk_bvh, meets) << "tile " << x0 << ", " << y0;
                if (!meets) EXPECT_TRUE(kept.empty()) << "tile " << x0 << ", " << y0;
                *gave_up += out.walk_bvh;
                continue;
            }
            if (out.walk_bvh) {
                ++*gave_up;
                EXPECT_GT(kept.size(), kMaxSubset) << "tile " << x0 << ", " << y0;
            } else {
                *listed += !kept.empty();
                EXPECT_EQ(out.prims, kept) << "tile " << x0 << ", " << y0;
            }
        }
}

TEST(TileCulling, ListsWhatTheFrustumKeepsOrGivesUpOnlyWhenTooMany) {
    static_assert(kMaxCulledPrimitives >= 320 && kMaxCulledPrimitives < 20480);
    for (const int subdivisions : {2, 5}) {  // 320 triangles, each over several tiles; 20,480, many in each
        int gave_up = 0, listed = 0;
        check_culling<double>(subdivisions, &gave_up, &listed);
        check_culling<float>(subdivisions, &gave_up, &listed);
        // The test has teeth: 320 triangles make both outcomes (340 lists,
        // 20 walks over both precisions), 20,480 make walks (344).
        EXPECT_GT(subdivisions == 2 ? listed : gave_up, 200) << subdivisions;
        if (subdivisions == 2) EXPECT_GT(gave_up, 0);
    }
}

}  // namespace
}  // namespace fh
