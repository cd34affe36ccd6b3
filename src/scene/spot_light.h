// Spot light (report 6.3), as SPEC section 4 reads it. For a point p with
// L = normalize(pos - p), d = |pos - p| and theta the angle between the cone's
// axis and the direction from the light to p:
//     intensity = I * (1 - theta / max_angle) / d^2   for theta <= max_angle, else 0.
// The report's formula (a parenthesis missing) divides by (1 - theta/max_angle)
// and so blows up at the cone's edge; this one falls smoothly to zero there.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/vec.h"

namespace fh {

template <typename T>
struct SpotRadiance {
    Vec3<T> to_light{0};  // unit, from the point toward the light
    T distance = 0;
    T intensity = 0;      // 0: the point gets nothing from this light
};

template <typename T>
struct SpotLight {
    std::string name;
    Color<T> color{0};
    T intensity = 0;
    Vec3<T> position{0};
    Vec3<T> axis{0, 0, -1};  // unit; the cone's axis, pointing away from the light
    T max_angle = T(2 * 3.14159265358979323846);  // radians
    bool on = true;
    bool cone_test = true;  // false when max_angle >= pi: every theta is inside

    SpotRadiance<T> radiance_at(const Vec3<T>& p) const {
        SpotRadiance<T> r;
        const Vec3<T> delta = position - p;
        const T d2 = glm::dot(delta, delta);
        // At the light's own position the direction is undefined: no light.
        if (!(d2 > T(0)) || !std::isfinite(d2)) return r;
        const T inv_distance = T(1) / std::sqrt(d2);
        r.distance = d2 * inv_distance;
        r.to_light = delta * inv_distance;
        // Rounding can push the cosine just past +-1; acos would return NaN.
        const T cos_theta = std::clamp(-glm::dot(r.to_light, axis), T(-1), T(1));
        const T theta = std::acos(cos_theta);
        if (cone_test && theta > max_angle) return r;
        // Right next to the light, d^2 can be so small (subnormal) that I / d^2
        // overflows to infinity. Capped at sqrt(max): finite, with room for the
        // colour products, and saturating every pixel it reaches anyway.
        const T cap = std::sqrt(std::numeric_limits<T>::max());
        r.intensity = std::min(cap, intensity * std::max(T(0), T(1) - theta / max_angle) / d2);
        return r;
    }
};

}  // namespace fh
