#include "scene/instance.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace fh {

std::vector<glm::dmat4> group_matrices(const std::vector<Group>& groups) {
    std::vector<glm::dmat4> world(groups.size());
    for (size_t g = 0; g < groups.size(); ++g) {
        const glm::dmat4 local = groups[g].transform.matrix();
        world[g] = groups[g].parent < 0 ? local : world[size_t(groups[g].parent)] * local;
    }
    return world;
}

bool group_holds(const std::vector<Group>& groups, std::size_t holder, int group) {
    for (int g = group; g >= 0; g = groups[size_t(g)].parent)
        if (size_t(g) == holder) return true;
    return false;
}

bool is_finite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

namespace {

// |v|, divided by its largest component first so that its square neither
// underflows (1e-200) nor overflows (1e200).
double length_of(const dvec3& v) {
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    return largest > 0 ? largest * glm::length(v / largest) : 0.0;
}

std::string scales_by(double scale) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", scale);
    return std::string("the transform scales by ") + text + " along an axis; the limit is 1e-12 to 1e12";
}

}  // namespace

std::string unusable_transform(const glm::dmat4& m) {
    if (!is_finite(m)) return "the transform is not finite";
    const glm::dmat3 a(m);
    dvec3 unit[3];
    for (int c = 0; c < 3; ++c) {
        const double length = length_of(a[c]);
        if (!(length > 0)) return "the transform is singular (it flattens space: no inverse)";
        if (!within_scale_limits(length)) return scales_by(length);
        unit[c] = a[c] / length;
    }
    // The volume of the unit columns' box: 0 when they lie in a plane,
    // whatever the scale.
    if (!(std::abs(glm::determinant(glm::dmat3(unit[0], unit[1], unit[2]))) > 1e-12))
        return "the transform is singular (it flattens space: no inverse)";
    // The tracer keeps an instance's maps in float too, both ways: a ray's
    // direction carried into the mesh's space, squared, must stay well
    // inside float's range (1e38). Its inverse's columns bound that.
    const glm::dmat3 inverse = glm::inverse(a);
    for (int c = 0; c < 3; ++c)
        if (const double length = length_of(inverse[c]); !within_scale_limits(length)) return scales_by(1 / length);
    return "";
}

glm::dmat4 usable_or_nothing(const glm::dmat4& m) {
    // Every frame, for every instance that moved, so first a test without a
    // square root that accepts only what unusable_transform does: columns
    // of squared length at least 1e-24 and all squares summing to at most
    // 1e24 (|A| <= 1e12: no column longer, and no inverse column shorter
    // than 1 / |A| >= 1e-12), |det|^2 > 1e-24 times the columns' squared
    // lengths (the unit columns' volume > 1e-12), and an inverse whose
    // squares sum to at most 1e24 (its columns no longer than 1e12).
    const glm::dmat3 a(m);
    const double c0 = glm::dot(a[0], a[0]), c1 = glm::dot(a[1], a[1]), c2 = glm::dot(a[2], a[2]);
    const double lo = kMinTransformScale * kMinTransformScale, hi = kMaxTransformScale * kMaxTransformScale;
    if (std::min({c0, c1, c2}) >= lo && c0 + c1 + c2 <= hi && std::isfinite(m[3].x + m[3].y + m[3].z)) {
        const double det = glm::determinant(a);
        if (det * det > 1e-24 * c0 * c1 * c2) {
            const glm::dmat3 inverse = glm::inverse(a);
            if (glm::dot(inverse[0], inverse[0]) + glm::dot(inverse[1], inverse[1]) + glm::dot(inverse[2], inverse[2]) <= hi)
                return m;
        }
    }
    if (unusable_transform(m).empty()) return m;
    glm::dmat4 nothing(0.0);
    nothing[3][3] = 1;
    return nothing;
}

}  // namespace fh
