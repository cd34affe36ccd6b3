// Camera paths (report section 10, SPEC section 5): how one camera property
// (a 3-vector) changes over a movie. Each value depends only on the global
// frame index and the frame count, so any subset of frames equals the same
// frames of a full run.
#pragma once

#include <variant>
#include <vector>

#include "core/vec.h"

namespace fh {

// center + sin(phi) * sin + cos(phi) * cos, phi = 2 pi turns i / N.
struct Orbit {
    dvec3 center{0};
    dvec3 sin{0};
    dvec3 cos{0};
    double turns = 1;
};

// normalize(point - view_point): for look_at, which is a direction.
struct Toward {
    dvec3 point{0};
};

enum class Interpolation { linear, catmull_rom };

struct Keyframe {
    int frame = 0;
    dvec3 value{0};
};

// Keys sorted by frame, frames distinct, at least one key. Before the first
// key and after the last the value holds. catmull_rom: a cubic Hermite curve
// through the keys whose tangent at each inner key is the finite difference
// of its neighbours (p[k+1] - p[k-1]) / (f[k+1] - f[k-1]), one-sided at the ends,
// so unevenly spaced keys are handled.
struct Keyframes {
    std::vector<Keyframe> keys;
    Interpolation interpolation = Interpolation::linear;
};

using Path = std::variant<dvec3, Orbit, Toward, Keyframes>;  // dvec3: a fixed value

// The value at frame i of n. view_point is only read by Toward.
dvec3 evaluate(const Path& path, int frame, int frame_count, const dvec3& view_point);

}  // namespace fh
