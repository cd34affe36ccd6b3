#include "anim/path.h"

#include <cmath>
#include <cstddef>
#include <numbers>

namespace fh {

namespace {

dvec3 evaluate_orbit(const Orbit& o, int frame, int frame_count) {
    // A movie without frames has no orbit to follow; phi = 0 keeps it finite.
    const double phi = frame_count > 0
        ? 2 * std::numbers::pi * o.turns * frame / frame_count
        : 0.0;
    return o.center + std::sin(phi) * o.sin + std::cos(phi) * o.cos;
}

// Tangent (value per frame) at key k: the finite difference of its neighbours,
// one-sided at the ends.
dvec3 tangent(const std::vector<Keyframe>& keys, std::size_t k) {
    const std::size_t lo = k == 0 ? k : k - 1;
    const std::size_t hi = k + 1 == keys.size() ? k : k + 1;
    return (keys[hi].value - keys[lo].value) / (keys[hi].frame - keys[lo].frame);
}

dvec3 hermite(const std::vector<Keyframe>& keys, std::size_t k, double t) {
    const double h = keys[k + 1].frame - keys[k].frame;
    const double t2 = t * t;
    const double t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1;
    const double h10 = t3 - 2 * t2 + t;
    const double h01 = -2 * t3 + 3 * t2;
    const double h11 = t3 - t2;
    return h00 * keys[k].value + h10 * h * tangent(keys, k) +
           h01 * keys[k + 1].value + h11 * h * tangent(keys, k + 1);
}

dvec3 evaluate_keyframes(const Keyframes& kf, int frame) {
    const std::vector<Keyframe>& keys = kf.keys;
    if (keys.empty()) return dvec3(0);  // the loader rejects this; stay defined
    const double f = frame;
    if (f <= keys.front().frame) return keys.front().value;
    if (f >= keys.back().frame) return keys.back().value;

    std::size_t k = 0;  // the segment [keys[k], keys[k + 1]) holding frame
    while (keys[k + 1].frame <= f) ++k;
    if (f == keys[k].frame) return keys[k].value;  // exact at keys

    const double t = (f - keys[k].frame) / (keys[k + 1].frame - keys[k].frame);
    auto mix = [&](double w) { return (1 - w) * keys[k].value + w * keys[k + 1].value; };
    switch (kf.interpolation) {
    case Interpolation::step: return keys[k].value;
    case Interpolation::catmull_rom: return hermite(keys, k, t);
    case Interpolation::ease_in: return mix(t * t);
    case Interpolation::ease_out: return mix(1 - (1 - t) * (1 - t));
    case Interpolation::ease_in_out: return mix(t * t * (3 - 2 * t));
    case Interpolation::linear: break;
    }
    return mix(t);
}

}  // namespace

dvec3 aim(const dvec3& from, const dvec3& to) {
    const dvec3 d = to - from;
    // Scale first so tiny or huge offsets do not under/overflow in length().
    // A zero offset stays the zero vector, for the frame checks to report.
    const double m = max_abs_component(d);
    if (m == 0 || !std::isfinite(m)) return m == 0 ? dvec3(0) : d;
    return glm::normalize(d / m);
}

dvec3 evaluate(const PointPath& path, int frame, int frame_count) {
    if (const auto* fixed = std::get_if<dvec3>(&path)) return *fixed;
    if (const auto* orbit = std::get_if<Orbit>(&path)) return evaluate_orbit(*orbit, frame, frame_count);
    return evaluate_keyframes(std::get<Keyframes>(path), frame);
}

dvec3 evaluate(const Path& path, int frame, int frame_count, const dvec3& origin) {
    if (const auto* fixed = std::get_if<dvec3>(&path)) return *fixed;
    if (const auto* orbit = std::get_if<Orbit>(&path)) return evaluate_orbit(*orbit, frame, frame_count);
    if (const auto* toward = std::get_if<Toward>(&path))
        return toward->follow ? dvec3(0) : aim(origin, evaluate(toward->point, frame, frame_count));
    return evaluate_keyframes(std::get<Keyframes>(path), frame);
}

}  // namespace fh
