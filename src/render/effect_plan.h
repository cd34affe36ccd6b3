// The effect plan: which of the report's effects can change this frame's
// pixels, worked out once per frame from the scene, the lights that are on,
// the effects list and max_depth. Everything else is not traced at all:
//   no glazed material, glazing off or max_depth 0  -> no reflection rays
//   a light that is off or has zero intensity       -> no shadow rays or shading for it
//   only ambient light                              -> no shadow rays at all
//   shadows off                                     -> no shadow rays
//   zero specular strength everywhere               -> no specular term
//   a spot light with max_angle >= pi               -> no cone test for it
// The shader is compiled once per combination of shadows, specular and
// glazing, so a switched-off effect costs nothing in the inner loop.
#pragma once

#include <string>
#include <vector>

#include "render/settings.h"
#include "scene/scene.h"

namespace fh {

struct EffectPlan {
    Effects effects;      // what is simulated
    int max_depth = 0;    // 0 when glazing is not simulated
    bool pruned = true;   // false: everything asked for is simulated (debug)
    bool mipmaps = true;  // RenderSettings::mipmaps: footprints worked out where a texture minifies
    // Why each effect asked for, or each light, is not simulated: "glazing: no
    // glazed material", "light 'spot': off".
    std::vector<std::string> skipped;

    // A light takes part in shading (it is on and has intensity).
    template <typename Light>
    bool uses(const Light& l) const {
        return !pruned || (l.on && l.intensity > 0);
    }
};

// prune = false keeps every effect the effects list and max_depth ask for, and
// every light, on or off (at zero weight when off): the image is the same
// bytes, only slower. Tests compare the two.
EffectPlan plan_effects(const Scene& scene, const Effects& asked, int max_depth, bool prune = true);
// The plan for a render's settings: their effects, depth, pruning and mipmaps.
EffectPlan plan_effects(const Scene& scene, const RenderSettings& settings);

// Shader variants: one bit per effect that changes the inner loop.
enum ShaderFeature : unsigned {
    kShadows = 1u << 0,
    kSpecular = 1u << 1,
    kGlazing = 1u << 2,
};
unsigned shader_features(const EffectPlan& plan);

}  // namespace fh
