// A glTF animation sampler, evaluated exactly as the glTF 2.0 specification's
// Appendix C defines it: keys at increasing times, and between them
//   STEP         the value of the key at or before t;
//   LINEAR       (1 - s) v_k + s v_k+1, s = (t - t_k) / (t_k+1 - t_k); a
//                rotation (a unit quaternion) by slerp along the shorter arc;
//   CUBICSPLINE  the cubic Hermite spline through v_k and v_k+1 whose
//                tangents are the keys' out- and in-tangents times the
//                interval t_k+1 - t_k.
// Before the first key a sampler holds the first value, after the last the
// last (so channels of different lengths share one clock). A rotation comes
// out unit length.
#pragma once

#include <string>
#include <vector>

namespace fh {

enum class Interpolation3 { step, linear, cubic_spline };  // glTF's three

struct Sampler {
    std::vector<double> times;   // seconds, strictly increasing, at least one
    // components values a key; CUBICSPLINE: three such groups a key, in
    // order in-tangent, value, out-tangent.
    std::vector<double> values;
    int components = 3;  // 3: translation or scale, 4: rotation (x, y, z, w), N: morph weights
    Interpolation3 interpolation = Interpolation3::linear;
    bool rotation = false;  // values are quaternions: slerp, and unit results

    double start() const { return times.front(); }
    double end() const { return times.back(); }
};

// The sampler's value at time t (components numbers).
std::vector<double> sample(const Sampler& sampler, double t);

// Why the sampler cannot be evaluated -- no key, times not finite or not
// increasing, too few values for its keys, a value not finite -- or empty.
std::string sampler_problem(const Sampler& sampler);

}  // namespace fh
