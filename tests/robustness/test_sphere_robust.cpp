// The sphere far away (hit or miss right at the
// silhouette, accurate t) and rays starting inside, on, or tangent to it.
// The truth is computed in long double from the exact float/double values
// the tracer is given (origin, centre, its rounded unit direction).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "core/exact.h"
#include "geometry/sphere.h"
#include "robust_util.h"

namespace fh {
namespace {

using namespace fh::robust;
using LD = long double;

template <typename T>
class SphereRobust : public ::testing::Test {};
TYPED_TEST_SUITE(SphereRobust, Scalars);

struct Truth {
    LD perpendicular;  // distance from the centre to the ray's line
    LD t_near, t_far;  // where the line crosses the sphere (if it does)
};

// The ray o + t d (d as given, not assumed unit) against the sphere (c, r).
template <typename T>
Truth truth(const Vec3<T>& o, const Vec3<T>& d, const Vec3<T>& c, T r) {
    const LD fx = LD(o.x) - LD(c.x), fy = LD(o.y) - LD(c.y), fz = LD(o.z) - LD(c.z);
    const LD dx = d.x, dy = d.y, dz = d.z;
    const LD dd = dx * dx + dy * dy + dz * dz;
    const LD cx = fy * dz - fz * dy, cy = fz * dx - fx * dz, cz = fx * dy - fy * dx;
    Truth tr;
    tr.perpendicular = std::sqrt((cx * cx + cy * cy + cz * cz) / dd);
    const LD along = -(fx * dx + fy * dy + fz * dz) / dd;  // t of the closest approach
    const LD half = std::sqrt(std::max(LD(0), LD(r) * LD(r) - tr.perpendicular * tr.perpendicular) / dd);
    tr.t_near = along - half;
    tr.t_far = along + half;
    return tr;
}

template <typename T>
Vec3<T> unit_direction(const dvec3& v) {
    return Vec3<T>(glm::normalize(v));
}

// Item 1. A unit sphere at distance D from the ray's origin, rays aimed within
// a few per cent of its silhouette. Stated accuracy, with eps the scalar's
// machine epsilon:
//   - silhouette: rays passing closer than r(1 - delta) hit, rays passing
//     farther than r(1 + delta) miss, with
//       delta = 16 eps                 for an origin at 0 (o - c exact),
//       delta = 16 eps + eps D / r     for an origin anywhere: o - c is
//                                      rounded to eps D / 2 per component
//                                      before anything else, which moves the
//                                      ray by as much relative to the sphere
//     (where the CPU has no FMA, add eps D / r to both);
//   - t: |t - t_true| <= 16 eps t_true + 2 sqrt(delta) r (the second term is
//     the square root's sensitivity at the edge of the band).
TYPED_TEST(SphereRobust, FarSphereSilhouetteAndDistance) {
    using T = TypeParam;
    const T eps = std::numeric_limits<T>::epsilon();
    std::mt19937_64 rng(20240401);
    std::uniform_real_distribution<double> unit01(0, 1);
    for (const bool at_zero : {true, false}) {
        for (const double D : {1e3, 1e4, 1e5, 1e6}) {
            const std::string where = std::string(at_zero ? "origin 0" : "origin anywhere") + ", D=" +
                                      std::to_string(D);
            double delta = 16 * double(eps) + (at_zero ? 0 : double(eps) * D);
            if (!kHardwareFma) delta += double(eps) * D;
            int hits = 0, misses = 0, wrong_hit = 0, wrong_miss = 0, bad_t = 0, nan = 0;
            for (int i = 0; i < 20000; ++i) {
                const Vec3<T> o = at_zero ? Vec3<T>(0)
                                          : Vec3<T>(20.0 * dvec3(unit01(rng), unit01(rng), unit01(rng)) - 10.0);
                const dvec3 u = random_unit(rng);
                const Sphere<T> s{Vec3<T>(dvec3(o) + D * u), T(1), 0};
                // Aim at distance h from the centre, h near 1 (most rays
                // within +-50 delta of the silhouette -- or of the
                // direction's own resolution at D, if larger -- and a few
                // anywhere in [0, 2]).
                const dvec3 w = random_perpendicular(rng, u);
                const double band = std::max(100 * delta, 8 * double(eps) * D);
                const double h = (i % 10 == 0) ? 2 * unit01(rng) : 1 + (unit01(rng) - 0.5) * band;
                const Vec3<T> d = unit_direction<T>(dvec3(s.center) + h * w - dvec3(o));
                const T t = s.intersect({o, d}, T(0), kInfinity<T>);
                if (std::isnan(t)) ++nan;
                const Truth tr = truth(o, d, s.center, s.radius);
                if (tr.perpendicular < LD(1 - delta)) {
                    ++hits;
                    if (t == kInfinity<T>) {
                        ++wrong_miss;
                    } else {
                        const LD tol = 16 * LD(eps) * tr.t_near + 2 * std::sqrt(LD(delta));
                        if (std::abs(LD(t) - tr.t_near) > tol) ++bad_t;
                    }
                } else if (tr.perpendicular > LD(1 + delta)) {
                    ++misses;
                    if (t != kInfinity<T>) ++wrong_hit;
                }
            }
            EXPECT_EQ(nan, 0) << where;
            EXPECT_EQ(wrong_miss, 0) << where << ": rays inside the silhouette that missed";
            EXPECT_EQ(wrong_hit, 0) << where << ": rays outside the silhouette that hit";
            EXPECT_EQ(bad_t, 0) << where << ": hits with t outside the stated error";
            EXPECT_GT(hits, 500) << where;
            EXPECT_GT(misses, 500) << where;
        }
    }
}

// Item 2a. Origin inside, from the centre to 1e-4 of the radius below the
// surface: the one root ahead is the far one, and it lies on the sphere to
// 16 eps r (the backward error; t itself is ill-conditioned for grazing
// rays from just under the surface).
TYPED_TEST(SphereRobust, OriginInsideTakesTheFarRoot) {
    using T = TypeParam;
    const T eps = std::numeric_limits<T>::epsilon();
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit01(0, 1);
    const Sphere<T> s{Vec3<T>(T(1.5), T(-2), T(0.75)), T(2), 0};
    int misses = 0, off_surface = 0, not_ahead = 0;
    for (int i = 0; i < 20000; ++i) {
        const double depth = std::pow(10.0, -4 * unit01(rng));  // 1 .. 1e-4 of the radius in
        const Vec3<T> o(dvec3(s.center) + (1 - depth) * double(s.radius) * random_unit(rng));
        const Vec3<T> d(random_unit(rng));
        const T t = s.intersect({o, d}, T(0), kInfinity<T>);
        const Truth tr = truth(o, d, s.center, s.radius);
        ASSERT_LT(tr.t_near, 0);
        if (!std::isfinite(t)) {
            ++misses;
            continue;
        }
        if (!(t > T(0))) ++not_ahead;
        const LD px = LD(o.x) + LD(t) * LD(d.x) - LD(s.center.x);
        const LD py = LD(o.y) + LD(t) * LD(d.y) - LD(s.center.y);
        const LD pz = LD(o.z) + LD(t) * LD(d.z) - LD(s.center.z);
        const LD residual = std::abs(std::sqrt(px * px + py * py + pz * pz) - LD(s.radius));
        if (residual > 16 * LD(eps) * LD(s.radius)) ++off_surface;
    }
    EXPECT_EQ(misses, 0) << "an origin inside always hits";
    EXPECT_EQ(not_ahead, 0);
    EXPECT_EQ(off_surface, 0) << "hit points farther than 16 eps r from the sphere";
}

// Item 2b. Origin on the surface (to the rounding of its coordinates): a ray
// going inward finds the far side -- not its own origin (t at least half the
// chord 2 r |d.n|) and on the sphere to 16 eps r -- and a ray going outward
// finds nothing. Grazing rays (|d.n| < 1e-3) may do either, never NaN.
TYPED_TEST(SphereRobust, OriginOnTheSurface) {
    using T = TypeParam;
    const T eps = std::numeric_limits<T>::epsilon();
    std::mt19937_64 rng(8);
    for (const double radius : {1e-3, 1.0, 1e3}) {
        const Sphere<T> s{Vec3<T>(T(1.5 * radius), T(-2 * radius), T(0.75 * radius)), T(radius), 0};
        int self_hits = 0, off_surface = 0, outward_hits = 0, nan = 0;
        for (int i = 0; i < 20000; ++i) {
            const dvec3 n = random_unit(rng);
            const Vec3<T> o(dvec3(s.center) + radius * n);
            const dvec3 dd = random_unit(rng);
            const Vec3<T> d(dd);
            const double cos_in = -glm::dot(dd, n);  // > 0: going inward
            const T t = s.intersect({o, d}, T(0), kInfinity<T>);
            if (std::isnan(t)) ++nan;
            if (cos_in > 1e-3) {
                if (!(double(t) > radius * cos_in)) {
                    ++self_hits;
                } else {
                    const LD px = LD(o.x) + LD(t) * LD(d.x) - LD(s.center.x);
                    const LD py = LD(o.y) + LD(t) * LD(d.y) - LD(s.center.y);
                    const LD pz = LD(o.z) + LD(t) * LD(d.z) - LD(s.center.z);
                    const LD residual = std::abs(std::sqrt(px * px + py * py + pz * pz) - LD(radius));
                    if (residual > 16 * LD(eps) * LD(radius)) ++off_surface;
                }
            } else if (cos_in < -1e-3) {
                if (t != kInfinity<T>) ++outward_hits;
            }
        }
        EXPECT_EQ(nan, 0) << "r=" << radius;
        EXPECT_EQ(self_hits, 0) << "r=" << radius << ": inward rays that hit their own origin";
        EXPECT_EQ(off_surface, 0) << "r=" << radius << ": far hits off the sphere by more than 16 eps r";
        EXPECT_EQ(outward_hits, 0) << "r=" << radius << ": outward rays that hit";
    }
}

// Item 2c. Tangent rays: the exactly tangent axis-aligned ray touches at its
// one root; rays within 1e-9 r of tangency hit near the touching point (within
// the half-chord such a ray can have) or miss, never NaN.
TYPED_TEST(SphereRobust, TangentRays) {
    using T = TypeParam;
    const T eps = std::numeric_limits<T>::epsilon();
    const Sphere<T> unit{Vec3<T>(0), T(1), 0};
    // Exactly tangent: passes (0, 1, 0) at t = 10, both roots equal.
    const T t = unit.intersect({{T(-10), T(1), T(0)}, {T(1), T(0), T(0)}}, T(0), kInfinity<T>);
    EXPECT_FALSE(std::isnan(t));
    EXPECT_EQ(t, T(10));

    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> unit01(0, 1);
    const Sphere<T> s{Vec3<T>(T(3), T(-1), T(2)), T(2), 0};
    int nan = 0, off = 0;
    for (int i = 0; i < 20000; ++i) {
        const dvec3 n = random_unit(rng);
        const dvec3 along = random_perpendicular(rng, n);
        const double h = 1 + (unit01(rng) - 0.5) * 2e-9;
        const dvec3 touch = dvec3(s.center) + h * double(s.radius) * n;
        const double back = 1 + 9 * unit01(rng);
        const Vec3<T> o(touch - back * along);
        const Vec3<T> d(along);
        const T th = s.intersect({o, d}, T(0), kInfinity<T>);
        if (std::isnan(th)) ++nan;
        // A hit lies within the half-chord a ray that close can have:
        // r sqrt(2 * 1e-9), plus the silhouette's own sensitivity.
        else if (th != kInfinity<T> && std::abs(double(th) - back) > 2 * std::sqrt(2e-9) * 1.01 +
                                                                    16 * double(eps) * back +
                                                                    4 * std::sqrt(double(eps)) * 2)
            ++off;
    }
    EXPECT_EQ(nan, 0);
    EXPECT_EQ(off, 0);
}

// Item 11 for these cases: a camera inside a sphere, and a far small sphere,
// rendered in both precisions; no sample is NaN or infinite, and from inside
// every pixel sees the sphere.
TYPED_TEST(SphereRobust, RenderedFromInsideAndFromFar) {
    using T = TypeParam;
    Scene s;
    const int m = add_material(s, "m", material({200, 100, 50}, 0.5, 0.5, 1, 10, true, 0.5));
    s.spheres().push_back({{0, 0, 0}, 5, m});
    s.spheres().push_back({{1e6, 0, 0}, 1e3, m});
    s.ambient_lights.push_back({"a", {255, 255, 255}, 1});
    s.directional_lights.push_back({"d", {255, 255, 255}, 0.01, glm::normalize(dvec3(1, 1, -1))});
    s.spot_lights.push_back({"s", {255, 255, 255}, 10, {0, 0, 4.9}, {0, 0, -1}, 6.283185307179586});
    const auto inside = render(s, camera(Projection::perspective, {0.5, -1, 0.2}, {1, 1, 0}, {0, 0, 1}, 48),
                               precision_of<T>(), all_effects());
    expect_finite_frame(inside, "camera inside a sphere");
    // Every pixel hit the sphere: none shows the background's red-to-yellow (blue = 0).
    int background = 0;
    for (int y = 0; y < 48; ++y)
        for (int x = 0; x < 48; ++x) background += inside.image.pixel(x, y)[2] == 0;
    EXPECT_EQ(background, 0);

    Scene far = s;
    far.spheres().erase(far.spheres().begin());
    // Sphere of radius 1e3 at 1e6: 1e-3 rad; at projection distance 5e3 a disc
    // of radius 5 units on the 20-unit-high image plane, 16 of its 64 pixels.
    const auto r = render(far, camera(Projection::perspective, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}, 64, 5e3),
                          precision_of<T>(), all_effects());
    expect_finite_frame(r, "far sphere");
    int hit = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) hit += r.image.pixel(x, y)[2] != 0;
    // A disc of radius 16 pixels: pi * 256 = 804 pixels.
    EXPECT_NEAR(hit, 804, 40);
}

}  // namespace
}  // namespace fh
