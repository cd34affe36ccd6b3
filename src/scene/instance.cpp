#include "scene/instance.h"

#include <cmath>

#include <glm/gtc/matrix_inverse.hpp>

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
    // Relative to the columns' sizes, so a uniformly tiny or huge scale is fine.
    const glm::dmat3 a(m);
    const double size = glm::length(a[0]) * glm::length(a[1]) * glm::length(a[2]);
    const double det = glm::determinant(a);
    if (!(size > 0) || !std::isfinite(size) || !(std::abs(det) > 1e-12 * size))
        return "the transform is singular (it flattens space: no inverse)";
    if (!is_finite(glm::inverse(m))) return "the transform has no finite inverse";
    return "";
}

}  // namespace fh
