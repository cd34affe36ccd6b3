// An axis-aligned box in double: a primitive's bounds, a BVH node's before
// it is rounded to floats (render/bvh.h).
#pragma once

#include <glm/common.hpp>

#include "core/vec.h"

namespace fh {

struct Aabb {
    dvec3 lo{kInfinity<double>};
    dvec3 hi{-kInfinity<double>};

    void grow(const dvec3& p) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    void grow(const Aabb& b) {
        lo = glm::min(lo, b.lo);
        hi = glm::max(hi, b.hi);
    }
    bool empty() const { return !(lo.x <= hi.x && lo.y <= hi.y && lo.z <= hi.z); }
    dvec3 center() const { return 0.5 * (lo + hi); }
    // Half the surface area: what the heuristic compares.
    double half_area() const {
        if (empty()) return 0;
        const dvec3 d = hi - lo;
        return d.x * d.y + d.y * d.z + d.z * d.x;
    }
};

}  // namespace fh
