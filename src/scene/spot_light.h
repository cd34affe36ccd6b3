// Spot light (report 6.3), as docs/model.md section 4 reads it. For a point p with
// L = normalize(pos - p), d = |pos - p| and theta the angle between the cone's
// axis and the direction from the light to p:
//     intensity = I * (1 - theta / max_angle) / d^2   for theta <= max_angle, else 0.
// The report's formula (a parenthesis missing) divides by (1 - theta/max_angle)
// and so blows up at the cone's edge; this one falls smoothly to zero there.
// A glTF spot (gltf_cone) falls off as KHR_lights_punctual's reference
// does instead: lit fully inside inner_angle, nothing past max_angle (its
// outerConeAngle), and in between smoothly in cos theta,
//     s = clamp((cos theta - cos max_angle) / (cos inner_angle - cos max_angle), 0, 1),
//     intensity = I * s^2 / d^2.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/fast_math.h"
#include "core/packet.h"

namespace fh {

// What one light gives each point of a packet.
template <typename T>
struct LightSample {
    Vec3Lanes<T> to_light;  // unit, from the point toward the light
    Lanes<T> distance;      // how far a shadow ray goes (infinity: a directional light)
    Lanes<T> intensity;     // 0: the point gets nothing from this light
};

// What radiance_at needs of a light's cone, worked out once a frame
// (FlatScene) rather than for every packet.
template <typename T>
struct SpotCone {
    // The widest theta that gets light: max_angle, or infinity where the
    // effect plan knows every theta is inside the cone (max_angle >= pi)
    // and skips the test.
    T widest_angle = kInfinity<T>;
    // A glTF cone: cos max_angle, and 1 / (cos inner_angle - cos max_angle)
    // (at most 1000, as the extension's sample code has it).
    T cos_outer = 0, scale = 0;
};

// The same for one point (tests, debugging).
template <typename T>
struct SpotRadiance {
    Vec3<T> to_light{0};
    T distance = 0;
    T intensity = 0;
};

template <typename T>
struct SpotLight {
    std::string name;
    Color<T> color{0};
    T intensity = 0;
    Vec3<T> position{0};
    Vec3<T> axis{0, 0, -1};  // unit; the cone's axis, pointing away from the light
    T max_angle = T(2 * 3.14159265358979323846);  // radians; infinite: a point light, no falloff with angle
    T inner_angle = 0;  // radians, in [0, max_angle): a glTF spot's inner cone, lit fully
    bool gltf_cone = false;  // a glTF spot: KHR_lights_punctual's falloff (above), not the report's
    bool on = true;
    int node = -1;  // a glTF light: the scene node that places and points it (scene/node.h)

    // Its cone's terms; widest_angle as SpotCone says.
    SpotCone<T> cone(T widest_angle) const {
        SpotCone<T> c{widest_angle};
        if (gltf_cone) {
            c.cos_outer = std::cos(max_angle);
            c.scale = T(1) / std::max(T(1e-3), std::cos(inner_angle) - c.cos_outer);
        }
        return c;
    }

    // For each point of a packet. Branch-free but for the kind of cone,
    // which is the light's.
    FH_HOT_INLINE LightSample<T> radiance_at(const Vec3Lanes<T>& p, const SpotCone<T>& c) const {
        const Vec3Lanes<T> delta = position - p;
        const Lanes<T> d2 = dot(delta, delta);
        // At the light's own position the direction is undefined: no light.
        const LaneInts<T> defined = (d2 > T(0)) & (d2 < kInfinity<T>);
        const Lanes<T> inv_distance = select(defined, T(1) / sqrt(d2), splat(T(0)));
        LightSample<T> r;
        r.distance = d2 * inv_distance;
        r.to_light = delta * inv_distance;
        // Rounding can push the cosine just past +-1, outside acos's domain.
        const Lanes<T> cos_theta = min(splat(T(1)), max(splat(T(-1)), -dot(r.to_light, axis)));
        const Lanes<T> theta = acos_fast(cos_theta);
        const LaneInts<T> inside = theta <= c.widest_angle;
        // Right next to the light, d^2 can be so small (subnormal) that I / d^2
        // overflows to infinity. Capped at sqrt(max): finite, with room for the
        // colour products, and saturating every pixel it reaches anyway.
        // (Products with reciprocals, not divisions: the slowest
        // instructions. falloff * inv_distance first, so a falloff of 0
        // stays 0 however large inv_distance^2 would be.)
        const T cap = std::sqrt(std::numeric_limits<T>::max());
        Lanes<T> cone;
        if (gltf_cone) {
            const Lanes<T> s = min(splat(T(1)), max(splat(T(0)), (cos_theta - c.cos_outer) * c.scale));
            cone = s * s;
        } else {
            cone = min(splat(T(1)), max(splat(T(0)), T(1) - theta * (T(1) / max_angle)));
        }
        const Lanes<T> falloff = min(splat(cap), intensity * (cone * inv_distance) * inv_distance);
        r.intensity = select(defined & inside, falloff, splat(T(0)));
        return r;
    }
    FH_HOT_INLINE LightSample<T> radiance_at(const Vec3Lanes<T>& p) const { return radiance_at(p, cone(max_angle)); }

    // One point: the packet formula with that point in every lane.
    SpotRadiance<T> radiance_at(const Vec3<T>& p) const {
        const LightSample<T> s = radiance_at(Vec3Lanes<T>::splat(p));
        return {s.to_light.lane(0), s.distance[0], s.intensity[0]};
    }
};

}  // namespace fh
