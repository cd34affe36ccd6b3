// No shadow acne. A plane and a sphere lit by directional
// lights (one steep, one grazing at 2 degrees), at scales 1e-3 .. 1e5 and
// moved far from the origin, for shadow rays and reflection rays.
//
// Two views of the same claim:
//  - per point: for every pixel's hit, the shadow ray toward each light that
//    faces the point, and the reflected ray, start at core/offset.h's origin
//    and must not find the very surface they leave (a plane is flat and the
//    sphere convex, so no such ray can meet its own surface again);
//  - per image: with the plane alone, or the sphere alone, switching shadows
//    on changes no pixel (nothing can shadow anything), and every reflection
//    ray leaves for the sky (as many reflection rays as pixels on the object).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/offset.h"
#include "geometry/plane.h"
#include "geometry/sphere.h"
#include "robust_util.h"
#include "scene/camera.h"
#include "render/flat_scene.h"  // Shape::surface: the hit point as shading finds it

namespace fh {
namespace {

using namespace fh::robust;

template <typename T>
class SelfIntersection : public ::testing::Test {};
TYPED_TEST_SUITE(SelfIntersection, Scalars);

constexpr int kImageSide = 64;

struct Setup {
    double scale;
    dvec3 shift;
};

// Scales 1e-3 .. 1e5, each at the origin and moved 1e3 scales away (1e5
// scales too in double, where that still leaves ~1e-10 scale resolution).
template <typename T>
std::vector<Setup> setups() {
    std::vector<Setup> out;
    for (const double s : {1e-3, 1e-1, 1.0, 1e2, 1e5}) {
        out.push_back({s, dvec3(0)});
        out.push_back({s, 1e3 * s * dvec3(1, -0.7, 0.4)});
        if (std::is_same_v<T, double>) out.push_back({s, 1e5 * s * dvec3(-0.6, 1, 0.8)});
    }
    return out;
}

std::string describe(const Setup& st) {
    return "scale " + std::to_string(st.scale) + " shift (" + std::to_string(st.shift.x) + ", " +
           std::to_string(st.shift.y) + ", " + std::to_string(st.shift.z) + ")";
}

const dvec3 kPlaneNormal = glm::normalize(dvec3(0.3, -0.2, 1));
const dvec3 kSteep = glm::normalize(dvec3(1, 0.5, -2));  // the way the light travels
// 2 degrees above the plane.
const dvec3 kGrazing = glm::normalize(glm::normalize(glm::cross(kPlaneNormal, dvec3(1, 0, 0))) -
                                      std::tan(2 * 3.14159265358979323846 / 180) * kPlaneNormal);

// The plane through `shift` and a sphere of radius `scale` resting 0.5 scale
// above it; lights and a camera that sees both, all scaled and moved alike.
Scene scene(const Setup& st, bool plane, bool sphere, bool glazed) {
    Scene s;
    const int m = add_material(s, "m", material({200, 200, 200}, 0.001, 1, 0.5, 20, glazed, 0.5));
    if (plane) s.planes.push_back({kPlaneNormal, glm::dot(kPlaneNormal, st.shift), m});
    if (sphere) s.spheres().push_back({st.shift + 1.5 * st.scale * kPlaneNormal, st.scale, m});
    s.ambient_lights.push_back({"a", {255, 255, 255}, 1});
    s.directional_lights.push_back({"steep", {255, 255, 255}, 0.05, kSteep});
    s.directional_lights.push_back({"grazing", {255, 255, 255}, 0.05, kGrazing});
    return s;
}

Camera view(const Setup& st) {
    const dvec3 eye = st.shift + st.scale * dvec3(0.5, -6, 4);
    const dvec3 at = st.shift + st.scale * dvec3(0, 0, 0.8);
    return camera(Projection::perspective, eye, at - eye, {0, 0, 1}, kImageSide, 25);
}

TYPED_TEST(SelfIntersection, NoRayFindsTheSurfaceItLeaves) {
    using T = TypeParam;
    for (const Setup& st : setups<T>()) {
        const Scene s = scene(st, true, true, true);
        const Sphere<T> sphere{Vec3<T>(s.spheres()[0].center), T(s.spheres()[0].radius), 0};
        const Plane<T> plane{Vec3<T>(s.planes[0].normal), T(s.planes[0].distance), 0};
        const CameraRays<T> rays(view(st));
        const Vec3<T> lights[2] = {-Vec3<T>(kSteep), -Vec3<T>(kGrazing)};
        int sphere_pixels = 0, plane_pixels = 0, shadow_acne = 0, reflection_acne = 0, shadow_rays = 0;
        for (int y = 0; y < kImageSide; ++y) {
            for (int x = 0; x < kImageSide; ++x) {
                const Ray<T> ray = rays.generate(T(x + 0.5), T(y + 0.5));
                const T ts = sphere.intersect(ray, T(0), kInfinity<T>);
                const T tp = plane.intersect(ray, T(0), ts);
                if (ts == kInfinity<T> && tp == kInfinity<T>) continue;
                const bool on_sphere = tp == kInfinity<T>;
                // The hit point and normal as shading finds them.
                Vec3<T> p, n;
                if (on_sphere) {
                    sphere.surface().project(ray.at(ts), p, n);
                    ++sphere_pixels;
                } else {
                    plane.surface().project(ray.at(tp), p, n);
                    ++plane_pixels;
                }
                if (glm::dot(n, ray.direction) > T(0)) n = -n;
                const Vec3<T> origin = offset_origin(p, n);
                auto hits_itself = [&](const Ray<T>& r) {
                    return on_sphere ? sphere.intersect(r, T(0), kInfinity<T>) != kInfinity<T>
                                     : plane.intersect(r, T(0), kInfinity<T>) != kInfinity<T>;
                };
                for (const Vec3<T>& l : lights) {
                    if (glm::dot(n, l) <= T(0)) continue;  // not lit: no shadow ray
                    ++shadow_rays;
                    shadow_acne += hits_itself({origin, l});
                }
                const Vec3<T> d = ray.direction;
                const Vec3<T> refl = glm::normalize(d - T(2) * glm::dot(d, n) * n);
                reflection_acne += hits_itself({origin, refl});
            }
        }
        EXPECT_GT(sphere_pixels, 200) << describe(st);
        EXPECT_GT(plane_pixels, 1000) << describe(st);
        EXPECT_GT(shadow_rays, 2000) << describe(st);
        EXPECT_EQ(shadow_acne, 0) << describe(st);
        EXPECT_EQ(reflection_acne, 0) << describe(st);
    }
}

// Pixels whose blue channel is not 0: the object (the sky's blue is 0).
int object_pixels(const Image& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) n += img.pixel(x, y)[2] != 0;
    return n;
}

TYPED_TEST(SelfIntersection, RenderedAloneNothingShadowsAndReflectionsLeave) {
    using T = TypeParam;
    for (const Setup& st : setups<T>()) {
        for (const bool plane : {true, false}) {
            const std::string what = describe(st) + (plane ? ", plane alone" : ", sphere alone");
            const Scene s = scene(st, plane, !plane, true);
            const Camera cam = view(st);
            const auto lit = render(s, cam, precision_of<T>(), effects(false, false));
            const auto shadowed = render(s, cam, precision_of<T>(), effects(true, false));
            expect_finite_frame(lit, what);
            expect_finite_frame(shadowed, what);
            EXPECT_EQ(count_differing_pixels(lit.image, shadowed.image), 0) << what << ": acne pixels";
            EXPECT_GT(shadowed.counts.shadow, 500u) << what;
            // Glazed, depth 5: a reflection ray that found its own surface
            // would spawn another one.
            const auto mirrored = render(s, cam, precision_of<T>(), effects(true, true));
            expect_finite_frame(mirrored, what);
            const int pixels = object_pixels(lit.image);
            EXPECT_GT(pixels, plane ? 1000 : 200) << what;
            EXPECT_EQ(mirrored.counts.reflection, std::uint64_t(pixels)) << what;
        }
        // Both together: finite everywhere.
        const auto both = render(scene(st, true, true, true), view(st), precision_of<T>(), all_effects());
        expect_finite_frame(both, describe(st) + ", plane and sphere");
    }
}

}  // namespace
}  // namespace fh
