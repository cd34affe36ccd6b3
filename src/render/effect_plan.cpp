#include "render/effect_plan.h"

#include <algorithm>

namespace fh {

namespace {

template <typename Pred>
bool any_material(const Scene& s, Pred p) {
    return std::any_of(s.materials.begin(), s.materials.end(), p);
}

// Turns `effect` off with a reason, if it was asked for.
void skip(EffectPlan& plan, bool& effect, const char* name, const std::string& why) {
    if (!effect) return;
    effect = false;
    plan.skipped.push_back(std::string(name) + ": " + why);
}

template <typename Light>
void note_unused_lights(EffectPlan& plan, const std::vector<Light>& lights) {
    for (const Light& l : lights) {
        if (!l.on) plan.skipped.push_back("light '" + l.name + "': off");
        else if (!(l.intensity > 0)) plan.skipped.push_back("light '" + l.name + "': intensity 0");
    }
}

}  // namespace

EffectPlan plan_effects(const Scene& scene, const Effects& asked, int max_depth, bool prune) {
    EffectPlan plan;
    plan.effects = asked;
    plan.pruned = prune;
    Effects& fx = plan.effects;
    if (max_depth <= 0) skip(plan, fx.glazing, "glazing", "max_depth is 0");
    if (!prune) {
        plan.max_depth = fx.glazing ? max_depth : 0;
        return plan;
    }
    note_unused_lights(plan, scene.ambient_lights);
    note_unused_lights(plan, scene.directional_lights);
    note_unused_lights(plan, scene.spot_lights);

    const bool ambient_light = std::any_of(scene.ambient_lights.begin(), scene.ambient_lights.end(),
                                           [&](const auto& l) { return plan.uses(l); });
    const bool direct_light =
        std::any_of(scene.directional_lights.begin(), scene.directional_lights.end(),
                    [&](const auto& l) { return plan.uses(l); }) ||
        std::any_of(scene.spot_lights.begin(), scene.spot_lights.end(),
                    [&](const auto& l) { return plan.uses(l); });

    if (!ambient_light) skip(plan, fx.ambient, "ambient", "no ambient light on");
    if (!any_material(scene, [](const auto& m) { return m.ambient > 0; }))
        skip(plan, fx.ambient, "ambient", "no material has ambient strength");
    for (auto [effect, name] : {std::pair{&fx.diffuse, "diffuse"}, {&fx.specular, "specular"},
                                {&fx.shadows, "shadows"}})
        if (!direct_light) skip(plan, *effect, name, "no directional or spot light on");
    // A metallic-roughness texture may give any hit diffuse and specular
    // strength, and a metal (metallic > 0.5) may be polished to a mirror.
    if (!any_material(scene, [](const auto& m) { return m.diffuse > 0 || m.metal_rough_texture >= 0; }))
        skip(plan, fx.diffuse, "diffuse", "no material has diffuse strength");
    if (!any_material(scene, [](const auto& m) { return m.specular > 0 || m.metal_rough_texture >= 0; }))
        skip(plan, fx.specular, "specular", "no material has specular strength");
    // Shadows only gate diffuse and specular.
    if (!fx.diffuse && !fx.specular) skip(plan, fx.shadows, "shadows", "no diffuse or specular term");
    if (!any_material(scene, [](const auto& m) { return m.may_mirror(); }))
        skip(plan, fx.glazing, "glazing", "no glazed material with reflectivity > 0");
    plan.max_depth = fx.glazing ? max_depth : 0;
    return plan;
}

EffectPlan plan_effects(const Scene& scene, const RenderSettings& settings) {
    EffectPlan plan = plan_effects(scene, settings.effects, settings.max_depth, settings.prune);
    plan.mipmaps = settings.mipmaps;
    return plan;
}

unsigned shader_features(const EffectPlan& plan) {
    return (plan.effects.shadows ? kShadows : 0u) | (plan.effects.specular ? kSpecular : 0u) |
           (plan.effects.glazing ? kGlazing : 0u);
}

}  // namespace fh
