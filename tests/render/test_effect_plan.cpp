// The effect plan: exact ray counts on small scenes, pruning never changes a
// byte, and each of the report's figures gets the plan docs/model.md section 6 gives it.
#include <gtest/gtest.h>

#include "yaml/scene_loader.h"
#include "render/render.h"

namespace fh {
namespace {

Material<double> matte(bool glazed = false) {
    Material<double> m;
    m.ambient_color = m.diffuse_color = m.specular_color = {200, 200, 200};
    m.ambient = 0.1;
    m.diffuse = 0.5;
    m.specular = 1;
    m.phong_exponent = 10;
    m.glazed = glazed;
    m.reflectivity = glazed ? 0.5 : 0;
    return m;
}

// A plane z = 0 seen from straight above by a 20x10 orthographic camera:
// every primary ray hits the plane, and every light above it faces it.
Scene floor_scene(int directional_lights, bool glazed) {
    Scene s;
    s.materials = {matte(glazed)};
    s.material_names = {"m"};
    s.planes.push_back({{0, 0, 1}, 0, 0});
    s.ambient_lights.push_back({"ambient", {255, 255, 255}, 0.01});
    for (int k = 0; k < directional_lights; ++k)
        s.directional_lights.push_back({"sun" + std::to_string(k), {255, 255, 255}, 0.01,
                                        glm::normalize(dvec3(0.1 * k, 0.2, -1))});
    Camera c;
    c.projection = Projection::orthographic;
    c.width = 20;
    c.height = 10;
    c.view_point = {0, 0, 5};
    c.look_at = {0, 0, -1};
    c.up = {0, 1, 0};
    s.cameras.push_back(c);
    return s;
}

FrameResult render_planned(const Scene& s, bool prune = true, int depth = 5) {
    RenderSettings settings;
    settings.max_depth = depth;
    settings.prune = prune;
    return render_frame(s, s.cameras.front(), settings, nullptr);
}

TEST(EffectPlan, ShadowRaysAreLightsTimesLitHits) {
    for (int k : {0, 1, 3}) {
        const auto r = render_planned(floor_scene(k, false));
        EXPECT_EQ(r.counts.primary, 200u);
        EXPECT_EQ(r.counts.shadow, 200u * unsigned(k)) << k << " lights";
        EXPECT_EQ(r.counts.reflection, 0u) << "nothing is glazed";
        EXPECT_EQ(r.plan.effects.shadows, k > 0);
    }
}

TEST(EffectPlan, GlazedFloorReflectsOncePerPixelAndOffLightsCastNothing) {
    Scene s = floor_scene(2, true);
    // The reflected rays go up into the sky: one each.
    EXPECT_EQ(render_planned(s).counts.reflection, 200u);
    EXPECT_EQ(render_planned(s, true, 0).counts.reflection, 0u);
    keep_only_lights(s, {"ambient", "sun1"});
    const auto r = render_planned(s);
    EXPECT_EQ(r.counts.shadow, 200u);  // sun0 is off: no shadow rays for it
    EXPECT_EQ(r.plan.skipped, std::vector<std::string>{"light 'sun0': off"});
    keep_only_lights(s, {"ambient"});
    EXPECT_EQ(render_planned(s).counts.shadow, 0u);  // only ambient light: none at all
}

TEST(EffectPlan, ReasonsForWhatIsSkipped) {
    Scene s = floor_scene(1, false);
    s.materials[0].specular = 0;
    Effects effects;
    effects.shadows = false;
    const EffectPlan plan = plan_effects(s, effects, 5);
    EXPECT_EQ(plan.effects.names(), "ambient diffuse");
    EXPECT_EQ(plan.skipped, (std::vector<std::string>{"specular: no material has specular strength",
                                                      "glazing: no glazed material with reflectivity > 0"}));
    EXPECT_EQ(plan_effects(s, effects, 0).skipped.front(), "glazing: max_depth is 0");
}

TEST(EffectPlan, PruningNeverChangesAByte) {
    const Scene report = load_scene(FIRSTHIT_SOURCE_DIR "/animations/scene.yaml").scene;
    struct Case {
        std::vector<std::string> lights;
        Projection projection;
    } cases[] = {{{"ambient", "spot"}, Projection::perspective},
                 {{"ambient", "directional"}, Projection::orthographic},
                 {{"ambient"}, Projection::perspective}};
    for (const auto& c : cases) {
        Scene s = report;
        keep_only_lights(s, c.lights);
        Camera cam = *s.find_camera(c.projection == Projection::perspective ? "perspective"
                                                                             : "orthographic");
        cam.width = cam.height = 200;
        s.cameras = {cam};
        const auto pruned = render_planned(s, true);
        const auto full = render_planned(s, false);
        EXPECT_EQ(pruned.image.rgb, full.image.rgb);
        EXPECT_LT(pruned.counts.shadow, full.counts.shadow);
        EXPECT_EQ(pruned.counts.primary, full.counts.primary);
    }
}

// docs/model.md section 6, and docs/model.md section 4 for which rays each effect needs.
TEST(EffectPlan, EachFigureGetsThePlanSpecGivesIt) {
    const char* expected[] = {
        "ambient",
        "ambient diffuse shadows",
        "ambient diffuse specular shadows",
        "ambient diffuse specular shadows glazing",
        "ambient diffuse specular shadows glazing",
        "ambient diffuse specular shadows glazing",
    };
    for (int n = 1; n <= 6; ++n) {
        const SceneFile f = load_scene(std::string(FIRSTHIT_SOURCE_DIR) + "/animations/figures/figure" +
                                       std::to_string(n) + ".yaml");
        const Scene& s = f.scene;
        const EffectPlan plan = plan_effects(s, f.settings.effects, f.settings.max_depth);
        EXPECT_EQ(plan.effects.names(), expected[n - 1]) << "figure " << n;
        EXPECT_EQ(s.directional_lights.size(), n >= 2 && n <= 4 ? 1u : 0u) << "figure " << n;
        EXPECT_EQ(s.spot_lights.size(), n >= 5 ? 1u : 0u) << "figure " << n;
        const auto flat = FlatScene<double>::build(s, plan);
        if (n == 1) EXPECT_TRUE(flat.directional_lights.empty() && flat.spot_lights.empty());
        // Figure 5's cone is 2 pi wide: no cone test. Figure 6's is pi/4.
        if (n == 5) EXPECT_EQ(flat.spot_cones.at(0).widest_angle, kInfinity<double>);  // no cone test
        if (n == 6) EXPECT_EQ(flat.spot_cones.at(0).widest_angle, flat.spot_lights.at(0).max_angle);  // cone tested
    }
}

}  // namespace
}  // namespace fh
