#include "scene/instance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/mat3x3.hpp>

namespace fh {

std::vector<glm::dmat4> group_matrices(const std::vector<Group>& groups) {
    std::vector<glm::dmat4> world(groups.size());
    for (size_t g = 0; g < groups.size(); ++g) {
        const glm::dmat4 local = groups[g].transform.matrix();
        world[g] = groups[g].parent < 0 ? local : world[size_t(groups[g].parent)] * local;
    }
    return world;
}

bool is_finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

std::string unusable_transform(const glm::dmat4& m) {
    if (!is_finite(m)) return "the transform is not finite";
    const glm::dmat3 a(m);
    dvec3 unit[3];
    for (int c = 0; c < 3; ++c) {
        // Divided by its largest component first, so that its square
        // neither underflows (1e-200) nor overflows (1e200).
        const double largest = std::max({std::abs(a[c].x), std::abs(a[c].y), std::abs(a[c].z)});
        const double length = largest > 0 ? largest * glm::length(a[c] / largest) : 0.0;
        if (!(length > 0)) return "the transform is singular (it flattens space: no inverse)";
        // The tracer keeps an instance's maps in float too: a ray's direction
        // through them, squared, must stay inside float's range (1e38).
        if (!(length >= kMinTransformScale && length <= kMaxTransformScale)) {
            char scale[32];
            std::snprintf(scale, sizeof scale, "%g", length);
            return std::string("the transform scales by ") + scale + " along an axis; the limit is 1e-12 to 1e12";
        }
        unit[c] = a[c] / length;
    }
    // The volume of the unit columns' box: 0 when they lie in a plane,
    // whatever the scale.
    if (!(std::abs(glm::determinant(glm::dmat3(unit[0], unit[1], unit[2]))) > 1e-12))
        return "the transform is singular (it flattens space: no inverse)";
    return "";
}

}  // namespace fh
