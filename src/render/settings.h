// What a render is asked to do: quality knobs and the effects switched on.
// A job's settings, travelling beside its Scene (which holds only what the
// scene file describes): a movie's `render:`/`effects:` and the command
// line's quality flags change these, never the Scene.
#pragma once

#include <string>

namespace fh {

enum class Precision { float32, float64 };  // the tracer's scalar type: float, double

inline const char* precision_name(Precision p) { return p == Precision::float32 ? "float" : "double"; }

// Documented limits: past these a request is refused as bad input rather than
// attempted (a 100000 x 100000 image would need 30 GB).
struct Limits {
    static constexpr int max_image_side = 16384;
    static constexpr int max_samples_per_pixel = 4096;
    static constexpr int max_depth = 64;
    // The largest light intensity and material strength (ambient, diffuse,
    // specular) and sphere or disk radius a file may give: every product
    // the tracer forms of them stays finite, in float too. (1e308 once made
    // every pixel NaN; a radius of 1e155 a sphere that vanished.)
    static constexpr double max_strength = 1e12;
    static constexpr double max_radius = 1e12;
};

// The effects of the report's shading (docs/model.md section 4).
struct Effects {
    bool ambient = true;
    bool diffuse = true;
    bool specular = true;
    bool shadows = true;
    bool glazing = true;

    std::string names() const {
        std::string s;
        auto add = [&](bool on, const char* n) {
            if (!on) return;
            if (!s.empty()) s += ' ';
            s += n;
        };
        add(ambient, "ambient");
        add(diffuse, "diffuse");
        add(specular, "specular");
        add(shadows, "shadows");
        add(glazing, "glazing");
        return s;
    }
};

struct RenderSettings {
    int samples_per_pixel = 1;
    int max_depth = 5;  // reflection rays a primary ray may spawn in a chain
    Precision precision = Precision::float64;
    // Adaptive anti-aliasing (render/adaptive.h): after the first pass, pixels
    // more than adaptive_threshold (0..255) from a neighbour get
    // adaptive_samples stratified samples instead.
    bool adaptive = false;
    double adaptive_threshold = 8;
    int adaptive_samples = 16;
    // Debug: false simulates every effect asked for, even those the effect
    // plan proves cannot change a pixel (render/effect_plan.h). Same bytes.
    bool prune = true;
    // Textures seen from afar read over each ray's footprint from their
    // mipmaps, as their files' minFilter asks (docs/gltf.md, "Textures");
    // false: every texture read as when magnified, one texel or four at
    // the hit (the accuracy knob --no-mipmaps: faster, aliased).
    bool mipmaps = true;
    Effects effects;  // asked for: the file's `effects:` list
};

}  // namespace fh
