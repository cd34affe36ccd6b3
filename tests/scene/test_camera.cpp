// Camera basis and the rays of corner and centre pixels of both cameras
// (report Table 6), against values worked out from docs/model.md section 3.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/camera.h"
#include "support/expect_vec.h"

namespace fh {
namespace {

Camera report_camera(Projection p) {
    Camera c;
    c.projection = p;
    c.view_point = {2, -10, 10};
    c.look_at = {0, 2, -1};
    c.up = {0, 0, 1};
    c.projection_distance = 10;
    return c;
}

using test::expect_vec_near;

TEST(Camera, ReportBasis) {
    // w = normalize(-(0,2,-1)) = (0,-2,1)/sqrt5; u = normalize(z x w) = (1,0,0);
    // v = w x u = (0,1,2)/sqrt5.
    const CameraBasis b = camera_basis({0, 2, -1}, {0, 0, 1});
    const double s5 = std::sqrt(5.0);
    expect_vec_near(b.w, {0, -2 / s5, 1 / s5}, 1e-15);
    expect_vec_near(b.u, {1, 0, 0}, 1e-15);
    expect_vec_near(b.v, {0, 1 / s5, 2 / s5}, 1e-15);
    EXPECT_FALSE(b.up_was_parallel);
}

// A look_at or up of 1e-300 or 1e300 -- a look_at of 1e-300 once made every
// ray NaN -- gives the basis of the same direction at everyday size, to the
// bit: the vectors are scaled by powers of two, which is exact. (So an
// everyday camera keeps its basis to the bit too: against the unscaled code,
// compiled alike at each level, 0 of 4 million random cameras differ.)
TEST(Camera, TinyOrHugeVectorsGiveTheEverydayBasis) {
    const CameraBasis everyday = camera_basis({0, 2, -1}, {0, 0, 1});
    for (const double size : {1e-300, 1e-200, 1e200, 1e300}) {
        const CameraBasis b = camera_basis(dvec3(0, 2, -1) * size, dvec3(0, 0, 1) * size);
        EXPECT_TRUE(b.w == everyday.w && b.u == everyday.u && b.v == everyday.v) << size;
        EXPECT_FALSE(b.up_was_parallel) << size;
    }
    Camera tiny = report_camera(Projection::perspective);
    tiny.look_at *= 1e-300;
    const Ray<double> r = CameraRays<double>(tiny).generate(0.5, 0.5);
    const Ray<double> e = CameraRays<double>(report_camera(Projection::perspective)).generate(0.5, 0.5);
    EXPECT_TRUE(r.direction == e.direction);
}

TEST(Camera, PerspectiveCornerAndCentreRays) {
    const CameraRays<double> rays(report_camera(Projection::perspective));
    // Pixel (0,0): x = -9.9875, y = 9.9875; dir = normalize(-10w + x u + y v).
    Ray<double> r = rays.generate(0.5, 0.5);
    expect_vec_near(r.origin, {2, -10, 10}, 0);
    expect_vec_near(r.direction, {-0.5771094055816303, 0.7749195522760243, 0.2577681545294987}, 1e-12);
    // Pixel (799,799): x = 9.9875, y = -9.9875.
    r = rays.generate(799.5, 799.5);
    expect_vec_near(r.direction, {0.5771094055816303, 0.25873720774201564, -0.7745965345385186}, 1e-12);
    // Pixel (400,400): x = 0.0125, y = -0.0125, just right of and below the centre.
    r = rays.generate(400.5, 400.5);
    expect_vec_near(r.direction, {0.001249998046879684, 0.8938667773397924, -0.44833092897217863}, 1e-12);
}

TEST(Camera, OrthographicCornerAndCentreRays) {
    const CameraRays<double> rays(report_camera(Projection::orthographic));
    const double s5 = std::sqrt(5.0);
    Ray<double> r = rays.generate(0.5, 0.5);
    // origin = (2,-10,10) + x u + y v with x = -9.9875, y = 9.9875.
    expect_vec_near(r.origin, {-7.9875, -5.53345421494417, 18.93309157011166}, 1e-12);
    expect_vec_near(r.direction, {0, 2 / s5, -1 / s5}, 1e-15);
    // The image centre (400, 400 as a continuous coordinate) is the view point.
    r = rays.generate(400, 400);
    expect_vec_near(r.origin, {2, -10, 10}, 1e-12);
}

TEST(Camera, WideImageWidensTheViewNotTheHeight) {
    Camera c = report_camera(Projection::orthographic);
    c.width = 1600;  // half_width = 20, half_height stays 10
    const CameraRays<double> rays(c);
    expect_vec_near(rays.generate(0, 800).origin - rays.generate(1600, 800).origin, {-40, 0, 0}, 1e-12);
}

TEST(Camera, UpParallelToViewUsesTheLeastAlignedAxis) {
    // Looking straight down with up = +z: the fallback up is x (first of the
    // axes least aligned with w = +z), so u = x cross w = (0,-1,0).
    const CameraBasis b = camera_basis({0, 0, -1}, {0, 0, 1});
    EXPECT_TRUE(b.up_was_parallel);
    expect_vec_near(b.w, {0, 0, 1}, 0);
    expect_vec_near(b.u, {0, -1, 0}, 1e-15);
    expect_vec_near(b.v, {1, 0, 0}, 1e-15);
    // The rays are finite everywhere.
    Camera c = report_camera(Projection::perspective);
    c.look_at = {0, 0, -1};
    const CameraRays<float> rays(c);
    for (float px : {0.f, 400.f, 800.f})
        for (float py : {0.f, 400.f, 800.f}) EXPECT_TRUE(is_finite(rays.generate(px, py).direction));
}

}  // namespace
}  // namespace fh
