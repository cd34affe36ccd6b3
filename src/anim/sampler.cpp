#include "anim/sampler.h"

#include <algorithm>
#include <cmath>

namespace fh {

namespace {

// Key k's value (its middle group for CUBICSPLINE), or its tangent: part 0
// the in-tangent, 2 the out-tangent.
const double* key(const Sampler& s, size_t k, int part = 1) {
    const size_t n = size_t(s.components);
    if (s.interpolation == Interpolation3::cubic_spline) return &s.values[(3 * k + size_t(part)) * n];
    return &s.values[k * n];
}

std::vector<double> unit(std::vector<double> q) {
    double len = 0;
    for (double c : q) len += c * c;
    len = std::sqrt(len);
    if (len > 0)
        for (double& c : q) c /= len;
    return q;
}

// Spherical linear interpolation of unit quaternions a and b at s, along
// the shorter arc (b negated when a . b < 0, the same rotation).
std::vector<double> slerp(const double* a, const double* b, double s) {
    double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    const double sign = d < 0 ? -1.0 : 1.0;
    d = std::abs(d);
    double wa = 1 - s, wb = s;
    // Nearly the same rotation: sin(angle) ~ 0, and linear is exact enough.
    if (d < 1 - 1e-12) {
        const double angle = std::acos(std::min(d, 1.0));
        const double sin_angle = std::sin(angle);
        wa = std::sin((1 - s) * angle) / sin_angle;
        wb = std::sin(s * angle) / sin_angle;
    }
    std::vector<double> q(4);
    for (int c = 0; c < 4; ++c) q[size_t(c)] = wa * a[c] + sign * wb * b[c];
    return unit(q);
}

}  // namespace

std::vector<double> sample(const Sampler& s, double t) {
    const size_t n = size_t(s.components);
    const size_t keys = s.times.size();
    auto value_of = [&](size_t k) {
        const double* v = key(s, k);
        std::vector<double> out(v, v + n);
        return s.rotation ? unit(out) : out;
    };
    if (keys == 1 || t <= s.times.front()) return value_of(0);
    if (t >= s.times.back()) return value_of(keys - 1);
    // The interval [t_k, t_k+1) holding t.
    const size_t k = size_t(std::upper_bound(s.times.begin(), s.times.end(), t) - s.times.begin()) - 1;
    const double td = s.times[k + 1] - s.times[k];
    const double u = (t - s.times[k]) / td;
    switch (s.interpolation) {
    case Interpolation3::step: return value_of(k);
    case Interpolation3::linear: {
        if (s.rotation) return slerp(key(s, k), key(s, k + 1), u);
        const double *a = key(s, k), *b = key(s, k + 1);
        std::vector<double> out(n);
        for (size_t c = 0; c < n; ++c) out[c] = (1 - u) * a[c] + u * b[c];
        return out;
    }
    case Interpolation3::cubic_spline: {
        const double u2 = u * u, u3 = u2 * u;
        const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
        const double *v0 = key(s, k), *b0 = key(s, k, 2), *v1 = key(s, k + 1), *a1 = key(s, k + 1, 0);
        std::vector<double> out(n);
        for (size_t c = 0; c < n; ++c) out[c] = h00 * v0[c] + h10 * td * b0[c] + h01 * v1[c] + h11 * td * a1[c];
        return s.rotation ? unit(out) : out;
    }
    }
    return value_of(k);
}

std::string sampler_problem(const Sampler& s) {
    if (s.times.empty()) return "it has no keys";
    if (s.components < 1) return "its values have no components";
    for (size_t k = 0; k < s.times.size(); ++k) {
        if (!std::isfinite(s.times[k])) return "key " + std::to_string(k) + "'s time is not finite";
        if (k > 0 && !(s.times[k] > s.times[k - 1]))
            return "its key times do not increase (key " + std::to_string(k) + ")";
    }
    const size_t groups = s.interpolation == Interpolation3::cubic_spline ? 3 : 1;
    if (s.values.size() < groups * s.times.size() * size_t(s.components))
        return "it has " + std::to_string(s.values.size()) + " values for " + std::to_string(s.times.size()) +
               " keys of " + std::to_string(s.components) + (groups == 3 ? " (times 3, CUBICSPLINE)" : "");
    for (const double v : s.values)
        if (!std::isfinite(v)) return "a value is not finite";
    return "";
}

}  // namespace fh
