// A tile's frustum (render/tile_culling.h) never drops a sphere that one of
// the tile's camera rays hits, and does drop the ones well outside it.
#include <gtest/gtest.h>

#include <random>

#include "render/tile_culling.h"

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
            const double x0 = 400 + 300 * u(rng), y0 = 300 + 200 * u(rng);
            const TileFrustum frustum(rays, x0, x0 + 16, y0, y0 + 16);
            // A sphere centred near a corner ray of the tile, at a random
            // depth, of a radius that makes it graze the tile or just miss.
            const Ray<double> corner = rays.generate(x0 + (u(rng) > 0 ? 16 : 0), y0 + (u(rng) > 0 ? 16 : 0));
            const double depth = 5 + 40 * (u(rng) + 1);
            const dvec3 off = glm::normalize(glm::cross(corner.direction, dvec3(u(rng), u(rng), u(rng))));
            const double radius = 0.05 + 2 * (u(rng) + 1);
            const Sphere<double> s{corner.at(depth) + (radius * (1 + 0.02 * u(rng))) * off, radius, 0};
            const bool hits = some_ray_hits(rays, x0, x0 + 16, y0, y0 + 16, s);
            const bool kept = frustum.may_hit(s.center, s.radius);
            if (hits) {
                ++hit;
                EXPECT_TRUE(kept) << "trial " << trial << ": a sphere the tile's rays hit was culled";
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

TEST(TileCulling, DropsSpheresWellOutsideTheTile) {
    for (const Projection projection : {Projection::perspective, Projection::orthographic}) {
        const CameraRays<double> rays(camera_of(projection, {0, -30, 20}));
        const TileFrustum frustum(rays, 392, 408, 292, 308);  // the middle of the image
        const Ray<double> centre = rays.generate(400, 300);
        EXPECT_TRUE(frustum.may_hit(centre.at(20), 0.1));
        const Ray<double> left = rays.generate(100, 300);
        EXPECT_FALSE(frustum.may_hit(left.at(20), 1.0)) << int(projection);
        // Behind the eye (perspective): outside the pyramid.
        if (projection == Projection::perspective) EXPECT_FALSE(frustum.may_hit(centre.at(-20), 0.01));
    }
}

}  // namespace
}  // namespace fh
