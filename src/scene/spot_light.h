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

#include "core/fast_math.h"

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

    SpotRadiance<T> radiance_at(const Vec3<T>& p) const { return radiance_at(p, widest_angle()); }

    // The widest theta that gets light.
    T widest_angle() const { return cone_test ? max_angle : kInfinity<T>; }

    // Branch-free, so the shading loop over a batch of points vectorises;
    // widest = widest_angle(), computed once outside that loop.
    FH_HOT_INLINE SpotRadiance<T> radiance_at(const Vec3<T>& p, T widest) const {
        const Vec3<T> delta = position - p;
        const T d2 = glm::dot(delta, delta);
        // At the light's own position the direction is undefined: no light.
        const bool defined = (d2 > T(0)) & (d2 < kInfinity<T>);
        const T inv_distance = defined ? T(1) / std::sqrt(d2) : T(0);
        SpotRadiance<T> r;
        r.distance = d2 * inv_distance;
        r.to_light = delta * inv_distance;
        // Rounding can push the cosine just past +-1, outside acos's domain.
        const T cos_theta = std::min(T(1), std::max(T(-1), -glm::dot(r.to_light, axis)));
        const T theta = acos_fast(cos_theta);
        const bool inside = theta <= widest;
        // Right next to the light, d^2 can be so small (subnormal) that I / d^2
        // overflows to infinity. Capped at sqrt(max): finite, with room for the
        // colour products, and saturating every pixel it reaches anyway.
        // (Products with reciprocals, not divisions: the loop's slowest
        // instructions. falloff * inv_distance first, so a falloff of 0
        // stays 0 however large inv_distance^2 would be.)
        const T cap = std::sqrt(std::numeric_limits<T>::max());
        const T cone = std::max(T(0), T(1) - theta * (T(1) / max_angle));
        const T falloff = std::min(cap, intensity * (cone * inv_distance) * inv_distance);
        r.intensity = (defined & inside) ? falloff : T(0);
        return r;
    }
};

}  // namespace fh
