// Each shading term at a hand-worked point (docs/model.md section 4): the report's
// plane (colour 130, ambient 0.1, diffuse 0.5, specular 10.5, exponent 100,
// glazed 0.05) under the report's lights.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "render/background.h"
#include "yaml/scene_loader.h"
#include "render/shading.h"

namespace fh {
namespace {

Material<double> plane_material() {
    Material<double> m;
    m.ambient_color = m.diffuse_color = m.specular_color = {130, 130, 130};
    m.ambient = 0.1;
    m.diffuse = 0.5;
    m.specular = 10.5;
    m.phong_exponent = 100;
    m.glazed = true;
    m.reflectivity = 0.05;
    return m;
}

// The plane z = -1 alone, with the report's ambient and directional lights.
Scene plane_scene() {
    Scene s;
    s.materials.push_back(plane_material());
    s.material_names.push_back("plane");
    s.planes.push_back({{0, 0, 1}, -1, 0});
    s.ambient_lights.push_back({"ambient", {255, 255, 255}, 0.002});
    s.directional_lights.push_back(
        {"directional", {255, 255, 230}, 0.02, glm::normalize(dvec3(-50, 50, -50))});
    return s;
}

Effects only(bool ambient, bool diffuse, bool specular) {
    Effects e;
    e.ambient = ambient;
    e.diffuse = diffuse;
    e.specular = specular;
    e.glazing = false;
    return e;
}

// The colour of one ray, through the shader variant the effect plan picks.
// These scenes have no instances: only the variants without them are
// compiled here (with_shader's instanced ones doubled this file's build).
Color<double> trace(const Scene& s, const Effects& fx, int depth, const Ray<double>& ray,
                    RayCounts& counts) {
    const auto flat = FlatScene<double>::build(s, plan_effects(s, fx, depth));
    if (flat.instances) throw std::logic_error("test_shading: a scene with instances");
    return with_shader_of<double, false>(flat, [&](const auto& shader) { return shader.trace(ray, counts); }, {});
}

Color<double> shade_from_above(const Scene& s, const Effects& fx, RayCounts* counts = nullptr) {
    RayCounts local;
    return trace(s, fx, 5, {{0, 0, 10}, {0, 0, -1}}, counts ? *counts : local);
}

void expect_color(const Color<double>& c, double r, double g, double b, double tol) {
    EXPECT_NEAR(c.r, r, tol);
    EXPECT_NEAR(c.g, g, tol);
    EXPECT_NEAR(c.b, b, tol);
}

TEST(Shading, Ambient) {
    // 0.002 * 0.1 * 255 * 130 = 6.63 on each channel.
    expect_color(shade_from_above(plane_scene(), only(true, false, false)), 6.63, 6.63, 6.63, 1e-12);
}

TEST(Shading, LambertUnderTheDirectionalLight) {
    // n.l = 1/sqrt3; 0.02 * 0.5 * (255*130, 255*130, 230*130) / sqrt3.
    expect_color(shade_from_above(plane_scene(), only(false, true, false)), 191.391614236361,
                 191.391614236361, 172.62773048769816, 1e-9);
}

TEST(Shading, BlinnPhongSpecular) {
    // view = (0,0,1); h = normalize(l + view); n.h = 0.8880738339771151;
    // 0.8880738...^100 * 0.02 * 10.5 * (255*130, 255*130, 230*130).
    expect_color(shade_from_above(plane_scene(), only(false, false, true)), 0.04870911694110497,
                 0.04870911694110497, 0.04393371331942801, 1e-12);
}

TEST(Shading, ShadowRayBlockedBySphereSkipsDiffuseAndSpecular) {
    Scene s = plane_scene();
    s.materials.push_back(plane_material());
    // A sphere between (0,0,-1) and the light (toward (1,-1,1)/sqrt3).
    s.spheres().push_back({{2, -2, 1}, 0.5, 1});
    RayCounts counts;
    expect_color(shade_from_above(s, only(true, true, true), &counts), 6.63, 6.63, 6.63, 1e-12);
    EXPECT_EQ(counts.shadow, 1u);
}

TEST(Shading, GlazingAddsTheReflectedBackground) {
    // Ambient 6.63 + 0.05 * background(up) = 0.05 * (255, 255, 0).
    Effects fx = only(true, false, false);
    fx.glazing = true;
    RayCounts counts;
    expect_color(shade_from_above(plane_scene(), fx, &counts), 6.63 + 12.75, 6.63 + 12.75, 6.63,
                 1e-12);
    EXPECT_EQ(counts.reflection, 1u);
    // Depth 0: no reflection ray.
    RayCounts none;
    expect_color(trace(plane_scene(), fx, 0, {{0, 0, 10}, {0, 0, -1}}, none), 6.63, 6.63, 6.63,
                 1e-12);
    EXPECT_EQ(none.reflection, 0u);
}

TEST(Shading, SpotLightFalloffOnThePlane) {
    Scene s = plane_scene();
    s.directional_lights.clear();
    s.spot_lights.push_back({"spot", {255, 255, 255}, 2.2, {0, 0, 10}, {0, 0, -1}, 2 * M_PI});
    // At (0,0,-1): intensity 2.2/121, n.l = 1, so diffuse = 2.2/121 * 0.5 * 255 * 130.
    expect_color(shade_from_above(s, only(false, true, false)), 2.2 / 121 * 0.5 * 255 * 130,
                 2.2 / 121 * 0.5 * 255 * 130, 2.2 / 121 * 0.5 * 255 * 130, 1e-9);
}

TEST(Shading, MissGivesTheSunset) {
    expect_color(background(dvec3(0, 0, 1)), 255, 255, 0, 0);
    expect_color(background(dvec3(0, 0, -1)), 255, 0, 0, 0);
    expect_color(background(dvec3(1, 0, 0)), 255, 127.5, 0, 0);
    RayCounts counts;
    expect_color(trace(Scene{}, Effects{}, 5, {{0, 0, 0}, {0, 0, 1}}, counts), 255, 255, 0, 0);
}

}  // namespace
}  // namespace fh

namespace fh {
namespace {

// Whole Phong exponents take square-and-multiply, one step per bit of the
// largest; only a fractional one needs std::pow (lane by lane, slow). A
// scene's materials must be read right for that: this once fell back to
// std::pow for every material and halved the frame rate, with the same bytes.
TEST(FlatScene, WholePhongExponentsTakeSquareAndMultiply) {
    Scene s = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml").scene;
    const auto report = FlatScene<double>::build(s, plan_effects(s, Effects{}, 5));
    EXPECT_FALSE(report.fractional_exponents);
    EXPECT_EQ(report.exponent_bits, 7);  // 100 = 0b1100100
    for (const auto& m : report.shading) EXPECT_TRUE(m.whole_exponent);
    s.materials[0].phong_exponent = 2.5;
    const auto fractional = FlatScene<double>::build(s, plan_effects(s, Effects{}, 5));
    EXPECT_TRUE(fractional.fractional_exponents);
    EXPECT_FALSE(fractional.shading[0].whole_exponent);
}

}  // namespace
}  // namespace fh
