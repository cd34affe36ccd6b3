// Movies: frame count, per-frame cameras, the docs/model.md section 5 orbits and the
// pre-render camera check.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "anim/movie.h"
#include "support/expect_vec.h"

namespace fh {
namespace {

using test::expect_vec_near;

// docs/model.md section 5: a full orbit over 10 s at 30 fps, always looking at the origin.
Movie spec_movie(double center_y, double center_z) {
    Movie m;
    m.fps = 30;
    m.seconds = 10;
    m.animate_camera(Property::camera_view_point, Orbit{dvec3(-10, center_y, center_z), dvec3(20, 0, 0), dvec3(0, 0, 15), 1});
    m.animate_camera(Property::camera_look_at, Toward{dvec3(0)});
    return m;
}

TEST(Movie, FrameCountRounds) {
    Movie m;
    EXPECT_EQ(m.frame_count(), 300);
    m.fps = 29.97;
    EXPECT_EQ(m.frame_count(), 300);  // 299.7
    m.fps = 24;
    m.seconds = 0.51;
    EXPECT_EQ(m.frame_count(), 12);  // 12.24
}

TEST(Movie, UnanimatedPropertiesKeepTheBaseCamera) {
    Movie m;
    m.camera.name = "perspective";
    m.camera.view_point = dvec3(2, -10, 10);
    m.camera.look_at = dvec3(0, 2, -1);
    m.camera.up = dvec3(0, 0, 1);
    m.animate_camera(Property::camera_view_point, Orbit{dvec3(0), dvec3(1, 0, 0), dvec3(0, 1, 0), 1});
    const Camera cam = camera_at(m, 75);
    EXPECT_EQ(cam.name, "perspective");
    EXPECT_EQ(cam.look_at, dvec3(0, 2, -1));
    EXPECT_EQ(cam.up, dvec3(0, 0, 1));
    expect_vec_near(cam.view_point, dvec3(1, 0, 0));  // phi = pi/2
}

// Movie 1: viewPoint(phi) = (-10 + 20 sin phi, -10, 16 + 15 cos phi),
// lookAt = normalize(-viewPoint). Frame 299: phi = 2 pi 299/300 = 2 pi - pi/150,
// sin phi = -sin(pi/150) = -0.0209424198833568, cos phi = 0.9997806834748455,
// so viewPoint = (-10.418848397667135, -10, 30.996710252122682), |viewPoint|^2 = 1169.3484...
TEST(Movie, SpecMovie1ByHand) {
    const Movie m = spec_movie(-10, 16);
    ASSERT_EQ(m.frame_count(), 300);
    struct Expect { int frame; dvec3 eye; dvec3 dir; };
    const Expect cases[] = {
        {0, {-10, -10, 31}, dvec3(10, 10, -31) / std::sqrt(1161.0)},
        {75, {10, -10, 16}, dvec3(-10, 10, -16) / std::sqrt(456.0)},
        {150, {-10, -10, 1}, dvec3(10, 10, -1) / std::sqrt(201.0)},
        {299, {-10.418848397667135, -10, 30.996710252122682},
         {0.3046826658883283, 0.29243411004670083, -0.9064495376954944}},
    };
    for (const Expect& e : cases) {
        SCOPED_TRACE(e.frame);
        const Camera cam = camera_at(m, e.frame);
        expect_vec_near(cam.view_point, e.eye);
        expect_vec_near(cam.look_at, e.dir);
    }
}

// Movie 2: viewPoint(phi) = (-10 + 20 sin phi, -40, 26 + 15 cos phi); frame 299
// as above: (-10.418848397667135, -40, 40.99671025212268), |viewPoint|^2 = 3389.2826...
TEST(Movie, SpecMovie2ByHand) {
    const Movie m = spec_movie(-40, 26);
    struct Expect { int frame; dvec3 eye; dvec3 dir; };
    const Expect cases[] = {
        {0, {-10, -40, 41}, dvec3(10, 40, -41) / std::sqrt(3381.0)},
        {75, {10, -40, 26}, dvec3(-10, 40, -26) / std::sqrt(2376.0)},
        {150, {-10, -40, 11}, dvec3(10, 40, -11) / std::sqrt(1821.0)},
        {299, {-10.418848397667135, -40, 40.99671025212268},
         {0.17896406027217704, 0.6870780855674934, -0.7041985298648421}},
    };
    for (const Expect& e : cases) {
        SCOPED_TRACE(e.frame);
        const Camera cam = camera_at(m, e.frame);
        expect_vec_near(cam.view_point, e.eye);
        expect_vec_near(cam.look_at, e.dir);
    }
}

TEST(Movie, SpecMoviesPassTheCheck) {
    EXPECT_TRUE(check_animations(spec_movie(-10, 16)).empty());
    EXPECT_TRUE(check_animations(spec_movie(-40, 26)).empty());
}

TEST(Movie, AnyFrameSubsetEqualsFullRun) {
    Movie m = spec_movie(-10, 16);
    m.animate_camera(Property::camera_up, Keyframes{{{0, dvec3(0, 0, 1)}, {150, dvec3(0, 1, 1)}, {299, dvec3(1, 0, 1)}},
                                                    Interpolation::catmull_rom});
    std::vector<Camera> full;
    for (int i = 0; i < m.frame_count(); ++i) full.push_back(camera_at(m, i));
    for (int i = 20; i >= 10; --i) {  // out of order, each on its own
        const Camera cam = camera_at(m, i);
        EXPECT_EQ(cam.view_point, full[i].view_point);
        EXPECT_EQ(cam.look_at, full[i].look_at);
        EXPECT_EQ(cam.up, full[i].up);
    }
}

TEST(Movie, ViewPointThroughTargetNamesTheFrame) {
    // x goes -7 -> 1 over frames 0..8: at frame 7, t = 7/8 and
    // (1/8)(-7) + (7/8)(1) = 0 exactly, so the eye sits on the target.
    Movie m;
    m.fps = 2;
    m.seconds = 10;
    m.animate_camera(Property::camera_view_point, Keyframes{{{0, dvec3(-7, 0, 0)}, {8, dvec3(1, 0, 0)}}, Interpolation::linear});
    m.animate_camera(Property::camera_look_at, Toward{dvec3(0)});
    EXPECT_EQ(camera_at(m, 7).look_at, dvec3(0));
    try {
        check_animations(m);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg, "camera.look_at is [0, 0, 0] at frame 7; a direction must not be zero");
    }
}

TEST(Movie, NonFiniteViewDirectionNamesTheFrame) {
    Movie m;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    m.animate_camera(Property::camera_look_at, Keyframes{{{3, dvec3(0, 0, -1)}, {4, dvec3(nan, 0, -1)}}, Interpolation::linear});
    try {
        check_animations(m);
        FAIL() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg, "camera.look_at is [nan, 0, -1] at frame 4; it must be finite");
    }
}

TEST(Movie, ParallelUpFramesAreReported) {
    // look_at = (sin phi, 0, cos phi) over 8 frames, up = +z: straight up at
    // frame 0, straight down at frame 4 (sin pi ~ 1e-16), sideways or oblique
    // elsewhere.
    Movie m;
    m.fps = 8;
    m.seconds = 1;
    m.camera.up = dvec3(0, 0, 1);
    m.animate_camera(Property::camera_look_at, Orbit{dvec3(0), dvec3(1, 0, 0), dvec3(0, 0, 1), 1});
    EXPECT_EQ(check_animations(m), (std::vector<int>{0, 4}));
    for (int i : {0, 4}) {
        SCOPED_TRACE(i);
        const Camera cam = camera_at(m, i);
        const CameraBasis b = camera_basis(cam.look_at, cam.up);
        EXPECT_TRUE(b.up_was_parallel);
        EXPECT_TRUE(is_finite(b.u) && is_finite(b.v) && is_finite(b.w));
        EXPECT_NEAR(glm::length(b.u), 1, 1e-12);
        EXPECT_NEAR(glm::length(b.v), 1, 1e-12);
        EXPECT_NEAR(glm::dot(b.u, b.w), 0, 1e-12);
        EXPECT_NEAR(glm::dot(b.v, b.w), 0, 1e-12);
    }
}

}  // namespace
}  // namespace fh
