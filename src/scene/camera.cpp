#include "scene/camera.h"

#include <cmath>

namespace fh {

CameraBasis camera_basis(const dvec3& look_at_as_given, const dvec3& up_as_given) {
    // (Scaled by powers of two: the same basis to the bit for everyday
    // vectors, and none of NaN for tiny or huge ones.)
    const dvec3 look_at = power_of_two_scaled(look_at_as_given), up = power_of_two_scaled(up_as_given);
    CameraBasis b;
    b.w = glm::normalize(-look_at);
    dvec3 side = glm::cross(up, b.w);
    // Parallel (or zero) up: a relative test, so the rule does not depend on
    // the length of `up`.
    const double up_len = glm::length(up);
    if (!(glm::length(side) > 1e-9 * up_len)) {
        b.up_was_parallel = true;
        const dvec3 a = glm::abs(b.w);
        dvec3 axis(0);
        if (a.x <= a.y && a.x <= a.z) axis.x = 1;
        else if (a.y <= a.z) axis.y = 1;
        else axis.z = 1;
        side = glm::cross(axis, b.w);
    }
    b.u = glm::normalize(side);
    b.v = glm::cross(b.w, b.u);
    return b;
}

}  // namespace fh
