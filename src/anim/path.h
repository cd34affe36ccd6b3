// Paths (report section 10, docs/model.md section 5): how one animated property (a
// 3-vector; a number or a flag travels in x) changes over a movie. Each value depends only on the global
// frame index and the frame count, so any subset of frames equals the same
// frames of a full run.
#pragma once

#include <optional>
#include <string>
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

// Between two keys, with t in [0, 1) the way from one to the next:
// step holds the first; linear mixes by t; catmull_rom below; the eases mix
// by t^2 (in), 1 - (1 - t)^2 (out), 3t^2 - 2t^3 (in and out: at rest at
// every key).
enum class Interpolation { step, linear, catmull_rom, ease_in, ease_out, ease_in_out };

struct Keyframe {
    double frame = 0;  // where the key is: a frame, or a time times fps (may fall between frames)
    dvec3 value{0};
};

// Keys in increasing order of frame, at least one key. Before the first
// key and after the last the value holds. catmull_rom: a cubic Hermite curve
// through the keys whose tangent at each inner key is the finite difference
// of its neighbours (p[k+1] - p[k-1]) / (f[k+1] - f[k-1]), one-sided at the ends,
// so unevenly spaced keys are handled.
struct Keyframes {
    std::vector<Keyframe> keys;
    Interpolation interpolation = Interpolation::linear;
};

// Where a point is at each frame: fixed, on an orbit, or keyframed.
using PointPath = std::variant<dvec3, Orbit, Keyframes>;

// A thing whose place a Toward can follow: a named surface (its centre) or a
// spot light (its position). The movie works out where it is (anim/movie.h).
struct Follow {
    bool spot_light = false;  // else a named surface
    size_t index = 0;         // into Scene::spot_lights or Scene::named_surfaces
    std::string path;         // as written: "surfaces.ball"
};

// A direction from the property's origin (the camera's view point, a spot
// light's position) toward a point: fixed, moving, or a followed thing.
struct Toward {
    PointPath point = dvec3(0);
    std::optional<Follow> follow;
};

using Path = std::variant<dvec3, Orbit, Toward, Keyframes>;  // dvec3: a fixed value

// The value at frame i of n. A Toward's point is aimed at from `origin`;
// a Toward that follows a thing is the movie's to resolve (this gives 0).
dvec3 evaluate(const Path& path, int frame, int frame_count, const dvec3& origin);
dvec3 evaluate(const PointPath& path, int frame, int frame_count);

// normalize(to - from), computed without under- or overflow; the zero
// vector when the two are the same point.
dvec3 aim(const dvec3& from, const dvec3& to);

}  // namespace fh
