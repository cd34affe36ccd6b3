// The disk, added through docs/architecture.md's walk-through: hits and
// misses worked by hand, its box, its surface; and a scene file's disk
// found by the tracer, with a nearer sphere and a farther plane around it.
#include <gtest/gtest.h>

#include "geometry/disk.h"
#include "render/packet_intersect.h"
#include "yaml/scene_loader.h"

namespace fh {
namespace {

template <typename T>
class DiskTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(DiskTest, Scalars);

TYPED_TEST(DiskTest, HitsInsideItsRadiusOnly) {
    using T = TypeParam;
    // The disk of radius 2 about (1, 1, 0) in the plane z = 0, seen from z = 5.
    const Disk<T> d{{1, 1, 0}, {0, 0, 1}, 2, 0};
    EXPECT_NEAR(d.intersect(Ray<T>{{1, 1, 5}, {0, 0, -1}}, 0, kInfinity<T>), 5, 1e-6);
    // 1.9 from the centre: a hit; 2.1: a miss; from below as from above.
    EXPECT_NEAR(d.intersect(Ray<T>{{2.9, 1, 5}, {0, 0, -1}}, 0, kInfinity<T>), 5, 1e-6);
    EXPECT_EQ(d.intersect(Ray<T>{{3.1, 1, 5}, {0, 0, -1}}, 0, kInfinity<T>), kInfinity<T>);
    EXPECT_NEAR(d.intersect(Ray<T>{{1, 2.5, -3}, {0, 0, 1}}, 0, kInfinity<T>), 3, 1e-6);
    // Going away from it, parallel to it, or stopped short of it: none.
    EXPECT_EQ(d.intersect(Ray<T>{{1, 1, 5}, {0, 0, 1}}, 0, kInfinity<T>), kInfinity<T>);
    EXPECT_EQ(d.intersect(Ray<T>{{-5, 1, 0.5}, {1, 0, 0}}, 0, kInfinity<T>), kInfinity<T>);
    EXPECT_EQ(d.intersect(Ray<T>{{1, 1, 5}, {0, 0, -1}}, 0, T(4.9)), kInfinity<T>);
    // An oblique ray: from (1, 1, 4) along (3, 0, -4) / 5 it reaches z = 0 at
    // t = 5, at (4, 1, 0), 3 from the centre: outside. Along (1, 0, -2) / sqrt 5 it
    // reaches (3, 1, 0) at t = 2 sqrt 5, exactly on the rim: inside (<=).
    EXPECT_EQ(d.intersect(Ray<T>{{1, 1, 4}, {T(0.6), 0, T(-0.8)}}, 0, kInfinity<T>), kInfinity<T>);
    const T s5 = std::sqrt(T(5));
    EXPECT_NEAR(d.intersect(Ray<T>{{1, 1, 4}, {1 / s5, 0, -2 / s5}}, 0, kInfinity<T>), 2 * s5, 1e-5);
}

TEST(Disk, BoxReachesRadiusTimesSineOfEachAxis) {
    // Normal (0, 0, 1): flat in z, the full radius in x and y.
    const Aabb flat = Disk<double>{{1, 2, 3}, {0, 0, 1}, 2, 0}.bounds();
    EXPECT_EQ(flat.lo, dvec3(-1, 0, 3));
    EXPECT_EQ(flat.hi, dvec3(3, 4, 3));
    // Normal (1, 0, 1) / sqrt 2: x and z reach r sqrt(1 - 1/2) = r / sqrt 2, y the full r.
    const double h = std::sqrt(0.5);
    const Aabb tilted = Disk<double>{{0, 0, 0}, {h, 0, h}, 2, 0}.bounds();
    EXPECT_NEAR(tilted.hi.x, 2 * h, 1e-15);
    EXPECT_NEAR(tilted.hi.y, 2, 1e-15);
    EXPECT_NEAR(tilted.hi.z, 2 * h, 1e-15);
}

TEST(Disk, ItsSurfaceIsFlatThroughItsCentre) {
    const PrimitiveSurface<double> s = Disk<double>{{1, 2, 3}, {0, 1, 0}, 2, 4}.surface();
    EXPECT_EQ(s.form, SurfaceForm::flat);
    EXPECT_EQ(s.material, 4);
    dvec3 p, n;
    s.project({1.5, 2.0001, 3.5}, p, n);  // a point just off it comes back onto its plane
    EXPECT_EQ(p.y, 2);
    EXPECT_EQ(n, dvec3(0, 1, 0));
}

TEST(Disk, ASceneFilesDiskIsTracedInIdOrder) {
    // A ray down the z axis meets the sphere (top at z = 4), the disk (z = 2)
    // and the floor (z = 0): without the sphere it stops at the disk, and the
    // disk's id comes after the sphere's, before the plane's.
    const std::string text =
        "materials:\n  m: {color: [200, 200, 200], ambient: 0.1, diffuse: 0.9, specular: 0, phong_exponent: 1}\n"
        "surfaces:\n"
        "  - {type: plane, normal: [0, 0, 1], distance: 0, material: m}\n"
        "  - {type: disk, center: [0, 0, 2], normal: [0, 0, 3], radius: 1, material: m}\n"
        "  - {type: sphere, center: [5, 0, 3], radius: 1, material: m}\n"
        "cameras:\n  c: {type: orthographic, width: 8, height: 8, view_point: [0, 0, 9], look_at: [0, 0, -1],"
        " up: [0, 1, 0]}\n";
    const Scene scene = load_scene_from_string(text, "disk.yaml").scene;
    ASSERT_EQ(scene.shapes.of<Disk>().size(), 1u);
    EXPECT_EQ(scene.shapes.of<Disk>()[0].normal, dvec3(0, 0, 1));  // made unit
    const FlatGeometry<double> g = FlatGeometry<double>::build(scene);
    EXPECT_EQ(g.ids.shapes, 2);  // the sphere (id 0), the disk (id 1)
    const Hit<double> down = closest_hit(g, Ray<double>{{0, 0, 9}, {0, 0, -1}});
    EXPECT_EQ(down.prim, 1);
    EXPECT_NEAR(down.t, 7, 1e-12);
    const Hit<double> beside = closest_hit(g, Ray<double>{{0, 1.5, 9}, {0, 0, -1}});
    EXPECT_EQ(beside.prim, g.ids.plane(0));  // past the disk's rim: the floor
    EXPECT_EQ(closest_hit(g, Ray<double>{{5, 0, 9}, {0, 0, -1}}).prim, 0);  // the sphere
}

}  // namespace
}  // namespace fh
